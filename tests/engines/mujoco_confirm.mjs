// The suite's findings on MuJoCo (examples/engines/mujoco_free_body.mjs), each confirmed by this
// test's own computation, written here without the suite: MuJoCo called directly (mj_step on one
// free body of its own model, as the wrapper steps it), the order of each integrator measured by
// self-convergence (the error at t = 1 against the same integrator at h = 1/4096, for h = 1/16 ...
// 1/256), and for RK4 the order of its attitude and of its angular velocity measured apart; and
// whether each keeps |q| = 1.
//
//   node tests/engines/mujoco_confirm.mjs REPORT_DIR/verdicts.json
//
// The order the suite measured (integrator_order's convergence series, in the claims of its verdict)
// must agree with this test's within 0.2 for every integrator; RK4's attitude must converge at order
// 2 and its angular velocity at order 4 or above (the suite's "Pi: at round-off, O: order 2.00":
// MuJoCo's RK4 turns the quaternion by each stage's velocity in turn, a product of exponentials,
// which is second order in the attitude). Exit status 0 when every finding agrees, 1 otherwise.
import { createRequire } from "node:module";
import * as fs from "node:fs";
import * as path from "node:path";
import { pathToFileURL } from "node:url";

const report = JSON.parse(fs.readFileSync(process.argv[2], "utf8"));
// MuJoCo as the example finds it (examples/engines/node_modules, installed by ./geomech test).
const examples = path.resolve(path.dirname(new URL(import.meta.url).pathname), "../../examples/engines");
const entry = createRequire(path.join(examples, "package.json")).resolve("mujoco-js");
const mujoco = await (await import(pathToFileURL(entry).href)).default();

const I = [1.75, 1.5, 1.25];
const q0 = [Math.cos(0.4), 0.6 * Math.sin(0.4), 0, 0.8 * Math.sin(0.4)];
const W0 = [0.7, -0.2, 0.4];

function run(integrator, h, t, each = () => {}) {
  const xml =
    `<mujoco><option gravity="0 0 0" timestep="${h}" integrator="${integrator}"/><worldbody><body>` +
    `<freejoint/><inertial pos="0 0 0" mass="1" diaginertia="${I.join(" ")}"/></body></worldbody></mujoco>`;
  mujoco.FS.writeFile("/confirm.xml", xml);
  const m = mujoco.MjModel.loadFromXML("/confirm.xml");
  const d = new mujoco.MjData(m);
  d.qpos.set([0, 0, 0, ...q0]);
  d.qvel.set([0, 0, 0, ...W0]);
  for (let n = Math.round(t / h); n > 0; n--) {
    mujoco.mj_step(m, d);
    each(Array.from(d.qpos).slice(3));
  }
  const out = { q: Array.from(d.qpos).slice(3), W: Array.from(d.qvel).slice(3) };
  d.delete();
  m.delete();
  return out;
}

const distance = (a, b) => Math.hypot(...a.map((v, i) => v - b[i]));
// The log-log slope of the error against h, least squares over the series.
function slope(errors, hs) {
  const x = hs.map(Math.log2), y = errors.map(Math.log2);
  const mx = x.reduce((a, b) => a + b) / x.length, my = y.reduce((a, b) => a + b) / y.length;
  let sxy = 0, sxx = 0;
  for (let i = 0; i < x.length; i++) (sxy += (x[i] - mx) * (y[i] - my)), (sxx += (x[i] - mx) ** 2);
  return sxy / sxx;
}

const hs = [1 / 16, 1 / 32, 1 / 64, 1 / 128, 1 / 256];
let compared = 0, disagreements = 0;
for (const integrator of ["Euler", "RK4", "implicit", "implicitfast"]) {
  const name = `mujoco_${integrator.toLowerCase()}`;
  const ref = run(integrator, 1 / 4096, 1);
  const e = { both: [], q: [], W: [] };
  for (const h of hs) {
    const x = run(integrator, h, 1);
    // q and -q are one attitude: the sign nearer the reference's.
    const q = distance(x.q, ref.q) <= distance(x.q.map((c) => -c), ref.q) ? x.q : x.q.map((c) => -c);
    e.q.push(distance(q, ref.q));
    e.W.push(distance(x.W, ref.W));
    e.both.push(Math.hypot(e.q.at(-1), e.W.at(-1)));
  }
  const own = slope(e.both, hs);
  for (const v of report.verdicts) {
    if (v.property !== "integrator_order" || v.integrator !== name) continue;
    const measured = (v.claims || []).find((c) => c.claim === "order")?.measured || "";
    const at = measured.indexOf("order ");
    if (at < 0) continue;
    const suite = parseFloat(measured.slice(at + 6));
    const agree = Math.abs(suite - own) <= 0.2;
    compared++;
    disagreements += !agree;
    console.log(`${name} order: suite '${measured}', this test ${own.toFixed(3)}${agree ? "" : "  <-- DISAGREE"}`);
  }
  // |q|^2 = 1 over 64 steps of h = 1/8, to a few roundings a step (MuJoCo normalises its quaternion),
  // against the suite's unit_quaternion row.
  let drift = 0;
  run(integrator, 1 / 8, 8, (q) => (drift = Math.max(drift, Math.abs(q.reduce((a, c) => a + c * c, 0) - 1))));
  const holds = drift <= 64 * 4 * Number.EPSILON;
  const row = (report.integrators.find((i) => i.name === name)?.claims || []).find((c) => c.claim === "unit_quaternion");
  if (row && row.status && row.status !== "-") {
    const suite = row.status.startsWith("holds (not claimed)") || row.status.startsWith("verified");
    compared++;
    disagreements += suite !== holds;
    console.log(`${name} unit_quaternion: suite '${row.status}', this test ${holds ? "holds" : "does not hold"} ` +
                `(largest | |q|^2 - 1 | over 64 steps of h = 1/8: ${drift.toExponential(2)})` +
                (suite === holds ? "" : "  <-- DISAGREE"));
  }
  if (integrator === "RK4") {
    // The velocity's error reaches double's round-off by h = 1/256: fitted over h = 1/16 ... 1/64.
    const q = slope(e.q, hs), W = slope(e.W.slice(0, 3), hs.slice(0, 3));
    const agree = Math.abs(q - 2) <= 0.2 && W >= 3.8;
    compared++;
    disagreements += !agree;
    console.log(`${name}: attitude order ${q.toFixed(3)}, angular velocity order ${W.toFixed(3)} ` +
                `(errors at h = 1/64: ${e.q[2].toExponential(2)}, ${e.W[2].toExponential(2)})` +
                (agree ? "" : "  <-- expected the attitude at order 2 and the velocity at 4"));
  }
}
if (compared < 9) {
  console.log(`only ${compared} findings compared (expected 4 orders, 4 unit quaternions and RK4's split): is ${process.argv[2]} the report of every integrator's integrator_order?`);
  process.exit(1);
}
console.log(`${compared} findings compared, ${disagreements} disagreements`);
process.exit(disagreements ? 1 : 0);
