// A line server for MuJoCo's step, for a wrapper in another language (mujoco_through_python.py):
// each line in is one step as JSON, {"integrator": "RK4", "I": [...], "q": [w, x, y, z],
// "Omega": [...], "h": ...}; each line out is {"q": [...], "Omega": [...]} or {"error": "..."}.
// Numbers that are not finite are written "NaN", "Infinity" or "-Infinity" (JSON.stringify would
// write null). The step itself is mujoco_free_body.mjs's, so the two wrappers step alike.
import { createInterface } from "node:readline";
import { mujoco_step } from "./mujoco_free_body.mjs";

const finite = (key, v) => (typeof v === "number" && !Number.isFinite(v) ? String(v) : v);

for await (const line of createInterface({ input: process.stdin })) {
  let reply;
  try {
    const r = JSON.parse(line);
    reply = mujoco_step(r.integrator, r.I, { q: r.q, Omega: r.Omega }, r.h);
  } catch (e) {
    reply = { error: `${e.name}: ${e.message}` };
  }
  process.stdout.write(JSON.stringify(reply, finite) + "\n");
}
