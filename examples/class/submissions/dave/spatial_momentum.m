function s = spatial_momentum(O, P)
  s = O * P;
end
