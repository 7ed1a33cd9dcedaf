// Buggy: Euler's equations with the cross product reversed, dPi/dt = Omega x Pi (the notes'
// (3.8) is dPi/dt = Pi x Omega). Everything else is correct.mjs. Caught by euler_form_3_8.
//   ./geomech check examples/students/bug_euler_sign.mjs
// The file it builds on is part of it (shown with it behind the sandbox, --untrusted):
// geomech: beside correct.mjs
export * from "./correct.mjs";

export const description = "Euler's equations with the cross product reversed (examples/students/bug_euler_sign.mjs)";

function cross(a, b) {
  return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
}

// (3.8): dPi/dt = Pi x I^-1 Pi
export function euler_3_8(I, P) {
  const Omega = P.map((p, k) => p / I[k]);
  return cross(Omega, P);  // the order of the factors is the sign of the whole right-hand side
}
