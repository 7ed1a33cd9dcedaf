function d = reconstruction_2_10(O, W)
  d = O * hat(W);
end
