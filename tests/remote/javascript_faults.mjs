// What can go wrong in a JavaScript implementation, one slot each, for the protocol's tests
// (tests/harness/remote/protocol_tests.cpp, RemoteSubject.JavaScript*): a step that computes a NaN
// (it crosses as what it is), a slot whose result is not finite, one that throws, one that returns
// nothing, and a vector in a typed array (a WebAssembly memory's view), which is accepted.
export const description = "a JavaScript file whose slots go wrong in every way a reply can";

export function hat(v) {
  throw new RangeError("hat is not written yet");
}

export function vee(m) {
  return [m[2][1], m[0][2], NaN];
}

export function casimir(Pi) {
  // nothing returned
}

export function euler_3_8(I, Pi) {
  const memory = new WebAssembly.Memory({ initial: 1 });
  const out = new Float64Array(memory.buffer, 0, 3);
  const W = [Pi[0] / I[0], Pi[1] / I[1], Pi[2] / I[2]];
  out[0] = Pi[1] * W[2] - Pi[2] * W[1];
  out[1] = Pi[2] * W[0] - Pi[0] * W[2];
  out[2] = Pi[0] * W[1] - Pi[1] * W[0];
  return out;
}

export const blows_up = {
  name: "blows_up",
  claims: { order: 1 },
  rigid_body_step(I, x, h) {
    return { Pi: [x.Pi[0] / 0, -x.Pi[1] / 0, 0 / 0], O: x.O };
  },
};
