// A correct JavaScript implementation of every slot (examples/students/correct.mjs), a port of
// correct.m, checked in double (JavaScript numbers are doubles):
//   ./geomech check examples/students/correct.mjs
// Every slot is an exported function named after it (`geomech slots --javascript`). Vectors arrive
// as arrays, matrices as arrays of rows, the Lie algebra as 'so3', 'so4' or 'sl2'; a pair is
// returned as a 2-array [a, b], a state as {Pi, O}.

export const description = "a correct JavaScript implementation (examples/students/correct.mjs)";

// ---- small linear algebra on arrays -----------------------------------------------------------

function cross(a, b) {
  return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
}

function dot(a, b) {
  let s = 0;
  for (let i = 0; i < a.length; i++) s += a[i] * b[i];
  return s;
}

function zeros(n, m) {
  const z = [];
  for (let i = 0; i < n; i++) z.push(new Array(m).fill(0));
  return z;
}

function eye(n) {
  const z = zeros(n, n);
  for (let i = 0; i < n; i++) z[i][i] = 1;
  return z;
}

function matmul(A, B) {
  const C = zeros(A.length, B[0].length);
  for (let i = 0; i < A.length; i++)
    for (let j = 0; j < B[0].length; j++) {
      let s = 0;
      for (let k = 0; k < B.length; k++) s += A[i][k] * B[k][j];
      C[i][j] = s;
    }
  return C;
}

function matvec(A, v) {
  return A.map((row) => dot(row, v));
}

function transpose(A) {
  return A[0].map((_, j) => A.map((row) => row[j]));
}

function madd(A, B, s = 1) {
  return A.map((row, i) => row.map((a, j) => a + s * B[i][j]));
}

function mscale(A, s) {
  return A.map((row) => row.map((a) => a * s));
}

function trace(A) {
  let s = 0;
  for (let i = 0; i < A.length; i++) s += A[i][i];
  return s;
}

// A \ B by Gaussian elimination with partial pivoting (what Octave's backslash does for a square
// A). B is a vector or a matrix (a list of rows); the answer has the same shape.
function solve(A, B) {
  const n = A.length;
  const isVector = !Array.isArray(B[0]);
  const M = A.map((row) => [...row]);
  const R = isVector ? B.map((b) => [b]) : B.map((row) => [...row]);
  for (let c = 0; c < n; c++) {
    let p = c;
    for (let r = c + 1; r < n; r++) if (Math.abs(M[r][c]) > Math.abs(M[p][c])) p = r;
    [M[c], M[p]] = [M[p], M[c]];
    [R[c], R[p]] = [R[p], R[c]];
    for (let r = c + 1; r < n; r++) {
      const f = M[r][c] / M[c][c];
      for (let k = c; k < n; k++) M[r][k] -= f * M[c][k];
      for (let k = 0; k < R[r].length; k++) R[r][k] -= f * R[c][k];
    }
  }
  for (let r = n - 1; r >= 0; r--) {
    for (let k = r + 1; k < n; k++)
      for (let j = 0; j < R[r].length; j++) R[r][j] -= M[r][k] * R[k][j];
    for (let j = 0; j < R[r].length; j++) R[r][j] /= M[r][r];
  }
  return isVector ? R.map((row) => row[0]) : R;
}

// Kronecker product, for the Sylvester equation of Manakov's Omega.
function kron(A, B) {
  const p = B.length, q = B[0].length;
  const K = zeros(A.length * p, A[0].length * q);
  for (let i = 0; i < A.length; i++)
    for (let j = 0; j < A[0].length; j++)
      for (let k = 0; k < p; k++)
        for (let l = 0; l < q; l++) K[i * p + k][j * q + l] = A[i][j] * B[k][l];
  return K;
}

// ---- so(3) and so(n) ----------------------------------------------------------------------------

// (2.11): hat(v) w = v x w.
export function hat(v) {
  return [[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]];
}

export function vee(m) {
  return [m[2][1], m[0][2], m[1][0]];
}

// (2.15): <A, B> = tr(A^T B) / 2.
export function pairing(a, b) {
  return trace(matmul(transpose(a), b)) / 2;
}

export function hat_n(v, n) {
  // so(n) from n(n-1)/2 coordinates: so(n-1) in the top-left block, the last column from the rest
  if (v.length !== (n * (n - 1)) / 2)
    throw new Error(`hat_n: ${v.length} coordinates do not make an element of so(${n})`);
  if (n === 2) return [[0, -v[0]], [v[0], 0]];
  if (n === 3) return hat(v);
  const d = ((n - 1) * (n - 2)) / 2;
  const m = zeros(n, n);
  const top = hat_n(v.slice(0, d), n - 1);
  for (let i = 0; i < n - 1; i++) {
    for (let j = 0; j < n - 1; j++) m[i][j] = top[i][j];
    m[i][n - 1] = v[d + i];
    m[n - 1][i] = -v[d + i];
  }
  return m;
}

export function vee_n(m) {
  const n = m.length;
  if (n === 2) return [m[1][0]];
  if (n === 3) return vee(m);
  const top = m.slice(0, n - 1).map((row) => row.slice(0, n - 1));
  return [...vee_n(top), ...m.slice(0, n - 1).map((row) => row[n - 1])];
}

// ---- matrix Lie algebras in coordinates (section 1) ----------------------------------------------

export function lie_hat(g, x) {
  switch (g) {
    case "so3":
      return hat_n(x, 3);
    case "so4":
      return hat_n(x, 4);
    case "sl2":
      return [[x[0], x[1]], [x[2], -x[0]]];
    default:
      throw new Error(`lie_hat: unknown algebra ${g}`);
  }
}

export function lie_vee(g, m) {
  if (g === "sl2") return [m[0][0], m[0][1], m[1][0]];
  return vee_n(m);
}

export function ad_star(g, xi, mu) {
  // (ad*_xi mu)_k = <mu, [xi, e_k]> in coordinates
  const d = xi.length;
  const a = new Array(d).fill(0);
  const X = lie_hat(g, xi);
  for (let k = 0; k < d; k++) {
    const e = new Array(d).fill(0);
    e[k] = 1;
    const E = lie_hat(g, e);
    a[k] = dot(mu, lie_vee(g, madd(matmul(X, E), matmul(E, X), -1)));
  }
  return a;
}

// so(4) as R^3 x R^3 (the SO(4) exercise): a = (u, v).
export function so4_bracket_R6(a, b) {
  const u1 = a.slice(0, 3), v1 = a.slice(3, 6), u2 = b.slice(0, 3), v2 = b.slice(3, 6);
  const top = cross(u1, u2).map((x, i) => x + cross(v1, v2)[i]);
  const bottom = cross(u1, v2).map((x, i) => x - cross(u2, v1)[i]);
  return [...top, ...bottom];
}

export function ad_star_so4_R6(xi, mu) {
  const xu = xi.slice(0, 3), xv = xi.slice(3, 6), mu_u = mu.slice(0, 3), mu_v = mu.slice(3, 6);
  const top = cross(mu_u, xu).map((x, i) => x + cross(mu_v, xv)[i]);
  const bottom = cross(mu_u, xv).map((x, i) => x + cross(mu_v, xu)[i]);
  return [...top, ...bottom];
}

// ---- Euler's equations ----------------------------------------------------------------------------

// (2.1): I1 dOmega1/dt = (I2 - I3) Omega2 Omega3 and cyclically.
export function euler_2_1(I, W) {
  return [
    ((I[1] - I[2]) * W[1] * W[2]) / I[0],
    ((I[2] - I[0]) * W[2] * W[0]) / I[1],
    ((I[0] - I[1]) * W[0] * W[1]) / I[2],
  ];
}

// (2.2): I dOmega/dt = I Omega x Omega.
export function euler_2_2(I, W) {
  const IW = I.map((i, k) => i * W[k]);
  return cross(IW, W).map((c, k) => c / I[k]);
}

// (3.7): dPi1/dt = (1/I3 - 1/I2) Pi2 Pi3 and cyclically.
export function euler_3_7(I, P) {
  return [
    (1 / I[2] - 1 / I[1]) * P[1] * P[2],
    (1 / I[0] - 1 / I[2]) * P[2] * P[0],
    (1 / I[1] - 1 / I[0]) * P[0] * P[1],
  ];
}

// (3.8): dPi/dt = Pi x Omega, Omega = I^-1 Pi.
export function euler_3_8(I, P) {
  return cross(P, P.map((p, k) => p / I[k]));
}

// (2.12), (2.20): dPi/dt = -[Omega_hat, Pi] with Omega = I^-1 vee(Pi).
export function euler_matrix_2_12(I, Pi_hat) {
  const W = hat(vee(Pi_hat).map((p, k) => p / I[k]));
  return madd(matmul(Pi_hat, W), matmul(W, Pi_hat), -1);
}

// ---- Lagrangian, Legendre transform, Hamiltonian -----------------------------------------------------

// (2.5): l = I Omega . Omega / 2.
export function lagrangian_2_5(I, W) {
  return dot(W, I.map((i, k) => i * W[k])) / 2;
}

// (2.13): l = <I Omega_hat, Omega_hat> / 2, with (I Omega)^ for the body's inertia.
export function lagrangian_2_13(I, W_hat) {
  return pairing(hat(I.map((i, k) => i * vee(W_hat)[k])), W_hat) / 2;
}

// (3.1): Pi = dl/dOmega = I Omega.
export function legendre_3_1(I, W) {
  return I.map((i, k) => i * W[k]);
}

// (3.5): Omega = dh/dPi = I^-1 Pi.
export function omega_3_5(I, P) {
  return P.map((p, k) => p / I[k]);
}

// (3.3): h = Pi . Omega - l(Omega).
export function hamiltonian_3_3(I, P) {
  const W = P.map((p, k) => p / I[k]);
  return dot(P, W) - lagrangian_2_5(I, W);
}

// (3.4): h = Pi . I^-1 Pi / 2.
export function hamiltonian_3_4(I, P) {
  return dot(P, P.map((p, k) => p / I[k])) / 2;
}

// (2.21): h = <Pi, Omega_hat> - l(Omega_hat).
export function hamiltonian_2_21(I, Pi_hat) {
  const W_hat = hat(vee(Pi_hat).map((p, k) => p / I[k]));
  return pairing(Pi_hat, W_hat) - lagrangian_2_13(I, W_hat);
}

// (2.27): the Casimir c(Pi) = |Pi|^2 / 2 of the bracket (3.6).
export function casimir(P) {
  return dot(P, P) / 2;
}

// ---- Poisson brackets (from gradients at a point) -----------------------------------------------------

// (2.23): {f, h} = -<Pi, [df, dh]>, the gradients as skew matrices.
export function lie_poisson_2_23(Pi_hat, df, dh) {
  return -pairing(Pi_hat, madd(matmul(df, dh), matmul(dh, df), -1));
}

// (3.6): {f, h} = -Pi . df x dh.
export function lie_poisson_3_6(P, df, dh) {
  return -dot(P, cross(df, dh));
}

// (3.13): {f, h} = -grad c . grad f x grad h.
export function nambu_3_13(dc, df, dh) {
  return -dot(dc, cross(df, dh));
}

// (3.14): dx/dt = grad c x grad h.
export function nambu_motion_3_14(dc, dh) {
  return cross(dc, dh);
}

// Section 3.5: the canonical bracket on T*R^3, {q_i, p_j} = delta_ij.
export function canonical_bracket(dfdq, dfdp, dhdq, dhdp) {
  return dot(dfdq, dhdp) - dot(dfdp, dhdq);
}

// (3.16)
export function nambu_3_16(a, x) {
  return [-a[0] * a[2] * x[1] * x[2], -a[1] * a[2] * x[2] * x[0], a[0] * a[1] * x[0] * x[1]];
}

// ---- momentum map, Clebsch, reconstruction, inertia -------------------------------------------------

// The momentum-map section: J = p x q.
export function momentum_map(q, p) {
  return cross(p, q);
}

// (3.21): Pi = P x Q, dQ/dt = -Omega x Q, dP/dt = -Omega x P.
export function clebsch_3_21(I, Q, P) {
  const W = cross(P, Q).map((p, k) => p / I[k]);
  return [cross(Q, W), cross(P, W)];
}

// (2.10): dO/dt = O Omega_hat.
export function reconstruction_2_10(O, W) {
  return matmul(O, hat(W));
}

// (2.30): the spatial angular momentum pi = O Pi.
export function spatial_momentum(O, P) {
  return matvec(O, P);
}

// Remark 2.1: I_space = O I O^-1 = O diag(I) O^T.
export function inertia_space(O, I) {
  const D = zeros(3, 3);
  for (let k = 0; k < 3; k++) D[k][k] = I[k];
  return matmul(matmul(O, D), transpose(O));
}

// (2.3): the inertia of point masses m[k] at the columns of X (3 x N).
export function inertia_tensor_2_3(m, X) {
  if (X.length !== 3 || X.some((row) => row.length !== m.length))
    throw new Error(`inertia_tensor_2_3: X must be 3 x N with N = ${m.length} masses`);
  let T = zeros(3, 3);
  for (let k = 0; k < m.length; k++) {
    const x = [X[0][k], X[1][k], X[2][k]];
    const xxT = x.map((a) => x.map((b) => a * b));
    T = madd(T, mscale(madd(mscale(eye(3), dot(x, x)), xxT, -1), m[k]));
  }
  return T;
}

// (2.3): (a, b) = sum m (a x X) . (b x X).
export function inertia_bilinear_2_3(m, X, a, b) {
  let s = 0;
  for (let k = 0; k < m.length; k++) {
    const x = [X[0][k], X[1][k], X[2][k]];
    s += m[k] * dot(cross(a, x), cross(b, x));
  }
  return s;
}

// ---- Manakov on so(n) (section 2.4) ---------------------------------------------------------------

// (2.34): M = A Omega + Omega A.
export function manakov_M(A, W) {
  return madd(matmul(A, W), matmul(W, A));
}

export function manakov_Omega(A, M) {
  // solve A W + W A = M (Sylvester equation): (kron(I, A) + kron(A^T, I)) vec(W) = vec(M),
  // vec stacking the columns
  const n = A.length;
  const K = madd(kron(eye(n), A), kron(transpose(A), eye(n)));
  const vecM = [];
  for (let j = 0; j < n; j++) for (let i = 0; i < n; i++) vecM.push(M[i][j]);
  const w = solve(K, vecM);
  const W = zeros(n, n);
  for (let j = 0; j < n; j++) for (let i = 0; i < n; i++) W[i][j] = w[j * n + i];
  return W;
}

// (2.34), (2.36): dM/dt = [M, Omega].
export function manakov_2_34(A, M) {
  const W = manakov_Omega(A, M);
  return madd(matmul(M, W), matmul(W, M), -1);
}

// Proposition 2.4: l = -tr(Omega A Omega) / 2.
export function manakov_lagrangian(A, W) {
  return -trace(matmul(matmul(W, A), W)) / 2;
}

// (3.23): M = Q^T P - P^T Q, (dQ/dt, dP/dt) = (Q Omega, P Omega).
export function manakov_clebsch_3_23(A, Q, P) {
  const W = manakov_Omega(A, madd(matmul(transpose(Q), P), matmul(transpose(P), Q), -1));
  return [matmul(Q, W), matmul(P, W)];
}

// ---- integrators ------------------------------------------------------------------------------

function midpoint_step(I, x0, h) {
  // Newton's method on F(N) = N - P - h f((P + N)/2), f(x) = x x (x ./ I) (3.8): a few iterations
  // where the fixed-point iteration needs tens at h = 1/4. With m = (P + N)/2,
  // dF/dN = Id - h/2 (hat(m) diag(1./I) - hat(m ./ I)).
  const P = x0.Pi;
  let nxt = P.map((p, k) => p + h * euler_3_8(I, P)[k]);
  const invI = zeros(3, 3);
  for (let k = 0; k < 3; k++) invI[k][k] = 1 / I[k];
  for (let it = 0; it < 50; it++) {
    const m = P.map((p, k) => (p + nxt[k]) / 2);
    const f = euler_3_8(I, m);
    const F = nxt.map((x, k) => x - P[k] - h * f[k]);
    const J = madd(eye(3), madd(matmul(hat(m), invI), hat(m.map((a, k) => a / I[k])), -1), -h / 2);
    const delta = solve(J, F);
    nxt = nxt.map((x, k) => x - delta[k]);
    // relative: the same step in any units
    if (Math.max(...delta.map(Math.abs)) <= 8 * Number.EPSILON * Math.max(...P.map(Math.abs))) break;
  }
  // the attitude by the Cayley transform of h hat(Omega_mid): O_1 = O_0 (Id - A/2)^-1 (Id + A/2)
  const A = mscale(hat(P.map((p, k) => (p + nxt[k]) / 2 / I[k])), h);
  const O = matmul(x0.O, solve(madd(eye(3), A, -1 / 2), madd(eye(3), A, 1 / 2)));
  return { Pi: nxt, O };
}

export const midpoint = {
  name: "midpoint",
  claims: { order: 2, symmetric: true, casimir: true, energy: true, orthogonality: true },
  rigid_body_step: midpoint_step,
};
