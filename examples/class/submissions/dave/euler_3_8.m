function d = euler_3_8(I, P)
  d = cross(P, omega_3_5(I, P));
end
