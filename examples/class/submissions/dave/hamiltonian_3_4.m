function h = hamiltonian_3_4(I, P)
  h = dot(P, P ./ I) / 2;
end
