// semi_implicit_euler.mjs with one conversion wrong inside each integrator's step, as wrappers and
// engines get them wrong (the JavaScript twin of bug_semi_implicit_euler.py). Each keeps its declared
// form, in the engine's WebAssembly memory as semi_implicit_euler.mjs does; the suite names the form
// in its answer.
//
//     ./geomech check examples/engines/bug_semi_implicit_euler.mjs
//
// - WorldOmega: world -> body with R instead of R^T (Omega = R omega): the step no longer returns its
//   own state as h -> 0 ("your step is not consistent in it").
// - BodyOmegaXYZW: the body's Omega applied on the world's side of q ((0, Omega) q instead of
//   q (0, Omega)): "your quaternion q = (x, y, z, w) turns with the body's Omega on the left".
// - MatrixSpatialMomentum: pi rebuilt with the attitude before the turn: "your pi ... follows dpi/dt".

// geomech: beside semi_implicit_euler.mjs
import {
  matvec, tmatvec, qmul, normalised, rotation, axis_angle, matmul, body_velocity_step, advance,
  heap, AT, store, rowsAt, PRECISION_REASON,
} from "./semi_implicit_euler.mjs";

export const description = "semi-implicit Euler in an engine's state forms, one conversion wrong in each step";

export const WorldOmegaTransposeSlip = {
  name: "world_omega_transpose_slip",
  state: "quaternion_wxyz omega",
  precision: "double",
  precision_reason: PRECISION_REASON,
  claims: { order: 1, unit_quaternion: true },
  rigid_body_step(I, x, h) {
    const q = store(AT.q, x.q, 4, "q"), w = store(AT.w, x.omega, 3, "omega");
    const R = rotation(q);
    w.set(body_velocity_step(I, matvec(R, w), h));   // the slip: R omega, not R^T omega
    const dq = qmul(q, [0.0, w[0], w[1], w[2]]);
    q.set(normalised(advance(q, dq, h)));
    w.set(matvec(rotation(q), w));
    return { q: Array.from(q), omega: Array.from(w) };
  },
};

export const BodyOmegaOnWorldSide = {
  name: "body_Omega_on_world_side",
  state: "quaternion_xyzw Omega",
  precision: "double",
  precision_reason: PRECISION_REASON,
  claims: { order: 1, unit_quaternion: true },
  rigid_body_step(I, x, h) {
    const s = store(AT.q, x.q, 4, "q"), w = store(AT.w, x.Omega, 3, "Omega");
    const [x_, y_, z_, w_] = s;
    w.set(body_velocity_step(I, w, h));
    const q = [w_, x_, y_, z_];
    const dq = qmul([0.0, w[0], w[1], w[2]], q);     // the slip: (0, Omega) q is the world's rate
    const [qw, qx, qy, qz] = normalised(advance(q, dq, h));
    s.set([qx, qy, qz, qw]);
    return { q: Array.from(s), Omega: Array.from(w) };
  },
};

export const MatrixMomentumStaleAttitude = {
  name: "matrix_pi_stale_attitude",
  state: "matrix pi",
  precision: "double",
  precision_reason: PRECISION_REASON,
  claims: { order: 1, orthogonality: true },
  rigid_body_step(I, x, h) {
    if (x.O == null || x.O.length !== 3) throw new TypeError("O must have 3 rows");
    x.O.forEach((row, i) => store(AT.O + 3 * i, row, 3, `row ${i} of O`));
    const rows = rowsAt(AT.O), p = store(AT.pi, x.pi, 3, "pi"), w = heap.subarray(AT.w, AT.w + 3);
    w.set(tmatvec(rows, p).map((c, k) => c / I[k]));
    w.set(body_velocity_step(I, w, h));
    const turned = matmul(rows, axis_angle(w, h));
    p.set(matvec(rows, [I[0] * w[0], I[1] * w[1], I[2] * w[2]]));   // the slip: O, not the turned O
    turned.forEach((row, i) => rows[i].set(row));
    return { O: rows.map((r) => Array.from(r)), pi: Array.from(p) };
  },
};
