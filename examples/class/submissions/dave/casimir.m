function c = casimir(P)
  c = dot(P, P) / 2;
end
