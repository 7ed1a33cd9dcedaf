function v = vee(m)
  v = [m(3, 2); m(1, 3); m(2, 1)];
end
