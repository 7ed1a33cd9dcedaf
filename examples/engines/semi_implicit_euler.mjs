// Semi-implicit Euler as physics engines write it, in the state forms engines keep (the JavaScript
// twin of semi_implicit_euler.py; bug_semi_implicit_euler.mjs imports its helpers).
//
// An engine steps the angular velocity first (explicitly, with the gyroscopic term), then turns the
// attitude with the new angular velocity and renormalises its quaternion. Each integrator below keeps
// its state in another form and says so in `state` (docs/STUDENTS.md, "State forms"); the suite
// converts to the notes' (Pi, O) with I, and this file converts nothing to them. The conversions an
// engine does inside its step (world to body and back) are its own, as in an engine.
//
//     ./geomech check examples/engines/semi_implicit_euler.mjs
//
// Each integrator claims what the method does: order 1, and its attitude kept exactly on SO(3)
// (unit_quaternion for a quaternion, renormalised every step; orthogonality for a matrix, turned by an
// exact rotation). Written for doubles, as an engine is: `precision` says so, with the reason.
//
// As an engine built to WebAssembly does, the body's state lives in a WebAssembly memory while a
// step computes: the step copies its arguments into the memory (a Float64Array view over it),
// computes on the view and copies plain arrays out. The quaternion's update q + (h/2) dq runs in
// WebAssembly code: `madd`, a hand-assembled module's one function (f64.mul, then f64.add: no fused
// multiply-add in WebAssembly, so it rounds as the Python's q[k] + h / 2 * dq[k] does). The arithmetic
// is the Python's, in the same order, so the results agree with it to round-off.

export const description = "semi-implicit Euler in an engine's state forms (quaternion, omega, Omega, pi)";

// ---- the engine's memory and its WebAssembly code ------------------------------------------------

// One 64 KiB page; the body's state as doubles at fixed places in it (indices into `heap`).
export const memory = new WebAssembly.Memory({ initial: 1 });
export const heap = new Float64Array(memory.buffer);
export const AT = Object.freeze({
  q: 0,    // the quaternion, 4 doubles, in the form's own order
  w: 4,    // the angular velocity (omega or Omega), 3 doubles
  O: 8,    // the attitude matrix, 9 doubles, row by row
  pi: 17,  // the spatial angular momentum pi, 3 doubles
});

// (module (import "env" "memory" (memory 1))
//   (func (export "madd") (param f64 f64 f64) (result f64)
//     local.get 0  local.get 1  f64.mul  local.get 2  f64.add))
const bytes = new Uint8Array([
  0x00, 0x61, 0x73, 0x6d,                     // magic "\0asm"
  0x01, 0x00, 0x00, 0x00,                     // version 1
  0x01, 0x08,                                 // type section, 8 bytes
  0x01, 0x60, 0x03, 0x7c, 0x7c, 0x7c, 0x01, 0x7c,  // 1 type: func (f64 f64 f64) -> (f64)
  0x02, 0x0f,                                 // import section, 15 bytes
  0x01, 0x03, 0x65, 0x6e, 0x76,               // 1 import: module "env"
  0x06, 0x6d, 0x65, 0x6d, 0x6f, 0x72, 0x79,   //   field "memory"
  0x02, 0x00, 0x01,                           //   a memory, limits: min 1 page, no max
  0x03, 0x02, 0x01, 0x00,                     // function section: 1 function, of type 0
  0x07, 0x08,                                 // export section, 8 bytes
  0x01, 0x04, 0x6d, 0x61, 0x64, 0x64, 0x00, 0x00,  // 1 export: "madd", a function, index 0
  0x0a, 0x0c,                                 // code section, 12 bytes
  0x01, 0x0a, 0x00,                           // 1 body, 10 bytes, no locals
  0x20, 0x00, 0x20, 0x01, 0xa2,               // local.get 0, local.get 1, f64.mul
  0x20, 0x02, 0xa0,                           // local.get 2, f64.add
  0x0b,                                       // end
]);
const engine = new WebAssembly.Instance(new WebAssembly.Module(bytes), { env: { memory } });

// madd(a, b, c) = a * b + c, each rounded, in WebAssembly.
export const madd = engine.exports.madd;

// Copies v into the memory at `at`, checking it has n entries.
export function store(at, v, n, what) {
  if (v == null || v.length !== n) throw new TypeError(`${what} must have ${n} entries`);
  heap.set(v, at);
  return heap.subarray(at, at + n);
}

// The rows of the 3x3 matrix kept row by row in the memory at `at` (views, not copies).
export function rowsAt(at) {
  return [0, 1, 2].map((i) => heap.subarray(at + 3 * i, at + 3 * i + 3));
}

// ---- small vector algebra on arrays, as an engine has it -----------------------------------------

export function cross(a, b) {
  return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
}

export function matvec(M, v) {
  const r = [];
  for (let i = 0; i < 3; i++) {
    let s = 0;
    for (let k = 0; k < 3; k++) s += M[i][k] * v[k];
    r.push(s);
  }
  return r;
}

export function tmatvec(M, v) {  // M^T v
  const r = [];
  for (let i = 0; i < 3; i++) {
    let s = 0;
    for (let k = 0; k < 3; k++) s += M[k][i] * v[k];
    r.push(s);
  }
  return r;
}

export function qmul(a, b) {  // Hamilton's product of (w, x, y, z) quaternions
  return [a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
          a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
          a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
          a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]];
}

export function normalised(q) {
  let s = 0;
  for (const c of q) s += c * c;
  const n = Math.sqrt(s);
  return Array.from(q, (c) => c / n);
}

export function rotation(q) {  // the rotation matrix of a unit quaternion (w, x, y, z): body -> world
  const [w, x, y, z] = q;
  return [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
          [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
          [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]];
}

export function axis_angle(v, h) {  // the rotation matrix exp(h hat(v)) (Rodrigues)
  let s2 = 0;
  for (const c of v) s2 += c * c;
  const a = Math.sqrt(s2);
  if (a === 0) return [[1, 0, 0], [0, 1, 0], [0, 0, 1]];
  const k = Array.from(v, (c) => c / a);
  const s = Math.sin(h * a), c = 1 - Math.cos(h * a);
  const K = [[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]];
  const K2 = matmul(K, K);
  const E = [];
  for (let i = 0; i < 3; i++) {
    const row = [];
    for (let j = 0; j < 3; j++) row.push((i === j ? 1 : 0) + s * K[i][j] + c * K2[i][j]);
    E.push(row);
  }
  return E;
}

export function matmul(A, B) {
  const C = [];
  for (let i = 0; i < 3; i++) {
    const row = [];
    for (let j = 0; j < 3; j++) {
      let s = 0;
      for (let m = 0; m < 3; m++) s += A[i][m] * B[m][j];
      row.push(s);
    }
    C.push(row);
  }
  return C;
}

// Omega <- Omega + h I^-1 ((I Omega) x Omega): Euler's equations (2.2), explicitly.
export function body_velocity_step(I, W, h) {
  const L = [I[0] * W[0], I[1] * W[1], I[2] * W[2]];
  const g = cross(L, W);
  return [0, 1, 2].map((k) => W[k] + h * g[k] / I[k]);
}

// q + (h/2) dq, each entry by the WebAssembly madd: (h/2) dq[k] + q[k].
export function advance(q, dq, h) {
  return [0, 1, 2, 3].map((k) => madd(h / 2, dq[k], q[k]));
}

// q <- normalise(q + (h/2) q (0, Omega)): the body's rate turns q on the body's side.
export function turn(q, W, h) {
  const dq = qmul(q, [0.0, W[0], W[1], W[2]]);
  return normalised(advance(q, dq, h));
}

// The reason every integrator here gives for its `precision`.
export const PRECISION_REASON = "written as an engine is, in a WebAssembly memory's doubles with Math.sqrt";

// ---- the integrators -----------------------------------------------------------------------------

// The engine's own form: a quaternion (w, x, y, z) and the world-frame angular velocity omega.
export const WorldOmega = {
  name: "semi_implicit_world_omega",
  state: "quaternion_wxyz omega",
  precision: "double",
  precision_reason: PRECISION_REASON,
  claims: { order: 1, unit_quaternion: true },
  rigid_body_step(I, x, h) {
    const q = store(AT.q, x.q, 4, "q"), w = store(AT.w, x.omega, 3, "omega");
    const R = rotation(q);
    w.set(body_velocity_step(I, tmatvec(R, w), h));   // world -> body: Omega = R^T omega
    q.set(turn(q, w, h));
    w.set(matvec(rotation(q), w));                     // body -> world with the new attitude
    return { q: Array.from(q), omega: Array.from(w) };
  },
};

// A quaternion stored (x, y, z, w), as in Bullet or Eigen's storage, and the body's Omega.
export const BodyOmegaXYZW = {
  name: "semi_implicit_body_Omega_xyzw",
  state: "quaternion_xyzw Omega",
  precision: "double",
  precision_reason: PRECISION_REASON,
  claims: { order: 1, unit_quaternion: true },
  rigid_body_step(I, x, h) {
    const q = store(AT.q, x.q, 4, "q"), w = store(AT.w, x.Omega, 3, "Omega");
    const [x_, y_, z_, w_] = q;
    w.set(body_velocity_step(I, w, h));
    const [qw, qx, qy, qz] = turn([w_, x_, y_, z_], w, h);
    q.set([qx, qy, qz, qw]);
    return { q: Array.from(q), Omega: Array.from(w) };
  },
};

// A rotation matrix and the spatial angular momentum pi, which a free body keeps.
export const MatrixSpatialMomentum = {
  name: "semi_implicit_matrix_pi",
  state: "matrix pi",
  precision: "double",
  precision_reason: PRECISION_REASON,
  claims: { order: 1, orthogonality: true },
  rigid_body_step(I, x, h) {
    if (x.O == null || x.O.length !== 3) throw new TypeError("O must have 3 rows");
    x.O.forEach((row, i) => store(AT.O + 3 * i, row, 3, `row ${i} of O`));
    const rows = rowsAt(AT.O), p = store(AT.pi, x.pi, 3, "pi"), w = heap.subarray(AT.w, AT.w + 3);
    w.set(tmatvec(rows, p).map((c, k) => c / I[k]));   // Omega = I^-1 O^T pi
    w.set(body_velocity_step(I, w, h));
    matmul(rows, axis_angle(w, h)).forEach((row, i) => rows[i].set(row));
    p.set(matvec(rows, [I[0] * w[0], I[1] * w[1], I[2] * w[2]]));   // pi = O I Omega, new O
    return { O: rows.map((r) => Array.from(r)), pi: Array.from(p) };
  },
};
