// geomech slot server for JavaScript implementations on Node (protocol: docs/PROTOCOL.md, version 2).
//
//     node geomech_server.mjs mine.mjs        (or mine.js: an ES module, or CommonJS's module.exports)
//
// Imports the student's file, finds the exported functions named after the harness's slots (the slot
// table comes from the harness in $GEOMECH_SLOT_TABLE; `geomech slots --javascript` prints it for
// people), probes each in double with small consistent arguments, writes the handshake line, then
// answers one request line with one reply line until its input ends.
//
// JavaScript numbers are IEEE doubles: the implementation is checked in double only, and the
// handshake says so for the 50-digit and exact scalars. Numbers cross as decimal strings written by
// the server (the shortest that reads back the same double), so a NaN or an infinity a step computes
// crosses as "nan", "inf" or "-inf", never as JSON.stringify's null. Node cannot fork, so the server
// offers no sessions: each check starts its own (docs/PROTOCOL.md, "Sessions").
//
// Replies go to the descriptor $GEOMECH_REPLY_FD (3), so the student's console.log can never be taken
// for one; without it (by hand), to stdout, and console.log goes to stderr.
import * as fs from "node:fs";
import * as path from "node:path";
import { pathToFileURL, fileURLToPath } from "node:url";

const PROTOCOL = "geomech-slots";
const VERSION = 2;
const SERVER_FILE = fileURLToPath(import.meta.url);

const replyFd = process.env.GEOMECH_REPLY_FD ? Number(process.env.GEOMECH_REPLY_FD) : 1;
if (!process.env.GEOMECH_REPLY_FD) {
  // By hand: the protocol on stdout, the student's console output on stderr.
  for (const k of ["log", "info", "debug"]) console[k] = (...a) => console.error(...a);
}

function reply(obj) {
  const data = Buffer.from(JSON.stringify(obj) + "\n", "utf8");
  let at = 0;
  while (at < data.length) at += fs.writeSync(replyFd, data, at, data.length - at);
}

// ---- signatures (the C++ text of the slot table: "Mat3<T>(const Vec3<T>& v)") --------------------

function splitTop(text) {
  const parts = [];
  let depth = 0, cur = "";
  for (const ch of text) {
    if (ch === "<" || ch === "(") depth++;
    else if (ch === ">" || ch === ")") depth--;
    if (ch === "," && depth === 0) {
      parts.push(cur);
      cur = "";
    } else {
      cur += ch;
    }
  }
  if (cur.trim()) parts.push(cur);
  return parts;
}

function kindOf(typeText) {
  let t = typeText.replace(/const/g, "").replace(/&/g, "").trim();
  t = t.split(/\s+/)[0] || t;
  const lt = t.indexOf("<");
  return lt >= 0 ? t.slice(0, lt) : t;  // T, Vec3, Mat3, Vec6, VecX, MatX, int, LieAlgebraId, ...
}

function parseSignature(sig) {
  let depth = 0;
  for (let i = 0; i < sig.length; i++) {
    const ch = sig[i];
    if (ch === "<") depth++;
    else if (ch === ">") depth--;
    else if (ch === "(" && depth === 0) {
      const args = sig.slice(i + 1, sig.lastIndexOf(")"));
      return [kindOf(sig.slice(0, i)), splitTop(args).map(kindOf)];
    }
  }
  throw new Error("bad signature " + sig);
}

// The integrator steps (the harness's slot table replaces these with its own list).
const STEP_SIGS = {
  rigid_body_step: ["RigidBodyState", ["Vec3", "RigidBodyState", "T"]],
  manakov_step: ["ManakovState", ["MatX", "ManakovState", "T"]],
  clebsch_step: ["Vec3Pair", ["Vec3", "Vec3Pair", "T"]],
  manakov_clebsch_step: ["MatXPair", ["MatX", "MatXPair", "T"]],
};

// ---- numbers: double only -----------------------------------------------------------------------

function number(text) {
  if (typeof text === "number") return text;
  const s = String(text);
  const slash = s.indexOf("/");
  if (slash >= 0) return Number(s.slice(0, slash)) / Number(s.slice(slash + 1));
  return Number(s);
}

function encodeNumber(x) {
  if (typeof x === "bigint") return x.toString();
  if (typeof x !== "number") {
    if (x instanceof Number) x = x.valueOf();
    else throw new TypeError("not a number: " + inert(describe(x)));
  }
  if (Number.isNaN(x)) return "nan";
  if (x === Infinity) return "inf";
  if (x === -Infinity) return "-inf";
  return String(x);  // the shortest decimal that reads back the same double
}

function describe(x) {
  if (x === undefined) return "undefined (a function that returns nothing?)";
  if (x === null) return "null";
  try {
    return typeof x === "object" ? JSON.stringify(x).slice(0, 200) : String(x);
  } catch {
    return typeof x;
  }
}

// A vector as a list: an Array, a typed array (Float64Array, a WebAssembly memory view) or any
// iterable; a column written as a list of 1-lists is accepted.
function asList(x, what) {
  if (x == null || typeof x === "string" || typeof x[Symbol.iterator] !== "function")
    throw new TypeError(what + " expected, got " + inert(describe(x)));
  const seq = Array.from(x);
  if (seq.length && seq.every((e) => e != null && typeof e === "object" && e.length === 1)) return seq.map((e) => e[0]);
  return seq;
}

function decode(kind, v) {
  switch (kind) {
    case "T":
      return number(v);
    case "int":
    case "LieAlgebraId":
      return v;
    case "Vec3":
    case "Vec4":
    case "Vec6":
    case "VecX":
      return v.map(number);
    case "Mat3":
    case "MatX":
      return v.map((row) => row.map(number));
    case "RigidBodyState":
      return { Pi: decode("Vec3", v.Pi), O: decode("Mat3", v.O) };
    case "ManakovState":
      return { M: decode("MatX", v.M), O: decode("MatX", v.O) };
    case "Vec3Pair":
      return [decode("Vec3", v[0]), decode("Vec3", v[1])];
    case "MatXPair":
      return [decode("MatX", v[0]), decode("MatX", v[1])];
  }
  if (kind.startsWith("EngineState:")) {  // a declared state form (docs/PROTOCOL.md, "State forms")
    const [, a, w] = kind.split(":");
    return { [a]: decode(a === "O" ? "Mat3" : "Vec4", v[a]), [w]: decode("Vec3", v[w]) };
  }
  throw new Error("unknown argument kind " + kind);
}

// The two parts of a state: an object with the keys (a class instance too), or a 2-array.
function parts(x, a, b) {
  if (x != null && typeof x === "object" && a in x) return [x[a], x[b]];
  if (Array.isArray(x) && x.length === 2) return x;
  throw new TypeError("a state with \"" + a + "\" and \"" + b + "\" expected, got " + inert(describe(x)));
}

function encode(kind, x) {
  switch (kind) {
    case "T":
      return encodeNumber(x);
    case "Vec3":
    case "Vec4":
    case "Vec6":
    case "VecX":
      return asList(x, "a vector").map(encodeNumber);
    case "Mat3":
    case "MatX":
      return asList(x, "a matrix (a list of rows)").map((row) => asList(row, "a matrix row").map(encodeNumber));
    case "Vec3Pair":
    case "MatXPair": {
      const part = kind === "Vec3Pair" ? "Vec3" : "MatX";
      const [q, p] = asList(x, "a pair [Q, P]");
      return [encode(part, q), encode(part, p)];
    }
    case "RigidBodyState": {
      const [Pi, O] = parts(x, "Pi", "O");
      return { Pi: encode("Vec3", Pi), O: encode("Mat3", O) };
    }
    case "ManakovState": {
      const [M, O] = parts(x, "M", "O");
      return { M: encode("MatX", M), O: encode("MatX", O) };
    }
  }
  if (kind.startsWith("EngineState:")) {
    const [, a, w] = kind.split(":");
    const [xa, xw] = parts(x, a, w);
    return { [a]: encode(a === "O" ? "Mat3" : "Vec4", xa), [w]: encode("Vec3", xw) };
  }
  throw new Error("unknown result kind " + kind);
}

// ---- the student's module -----------------------------------------------------------------------

// Text from the student's code as it may travel: a lone surrogate becomes the visible \udXXX.
function inert(text) {
  return String(text).replace(/[\ud800-\udfff]/g, (c, i, s) => {
    const code = c.charCodeAt(0);
    const pair = code < 0xdc00 ? s.charCodeAt(i + 1) : s.charCodeAt(i - 1);
    const paired = code < 0xdc00 ? pair >= 0xdc00 && pair <= 0xdfff : pair >= 0xd800 && pair < 0xdc00;
    return paired ? c : "\\u" + code.toString(16);
  });
}

// The error's stack without the server's own frames.
function studentTraceback(e) {
  if (!(e instanceof Error)) return inert("uncaught value thrown: " + describe(e));
  const lines = String(e.stack || e).split("\n").filter((l) => !l.includes(SERVER_FILE));
  return inert(lines.join("\n").trimEnd());
}

function firstLine(e) {
  if (!(e instanceof Error)) return inert("uncaught value thrown: " + describe(e));
  return inert(`${e.name}: ${e.message}`.split("\n")[0]);
}

function get(obj, key) {
  return obj != null && (typeof obj === "object" || typeof obj === "function") ? obj[key] : undefined;
}

// The argument kind of a rigid-body step kept in a declared form ("quaternion_wxyz omega").
function stateKind(words) {
  const w = String(words).replace(/,/g, " ").split(/\s+/).filter(Boolean);
  if (w.length !== 2) return null;
  return `EngineState:${w[0] === "matrix" ? "O" : "q"}:${w[1]}:${w[0]}`;
}

// An integrator: an exported object with a `name` and step functions, or an exported class, whose
// static step functions are used, or else an instance made with `new` (no arguments) with its methods.
function integratorOf(value) {
  const steps = (o) => Object.keys(STEP_SIGS).filter((s) => typeof get(o, s) === "function");
  if (typeof value === "function" && /^class[\s{]/.test(Function.prototype.toString.call(value))) {
    if (steps(value).length) return { obj: value, name: value.name, steps: steps(value) };
    let made;
    try {
      made = new value();
    } catch {
      return null;
    }
    const s = steps(made);
    if (!s.length) return null;
    for (const k of s) made[k] = made[k].bind(made);
    return { obj: made, name: get(made, "name") ?? value.name, steps: s };
  }
  if (value != null && typeof value === "object" && !Array.isArray(value)) {
    const s = steps(value);
    if (s.length && get(value, "name")) return { obj: value, name: value.name, steps: s };
  }
  return null;
}

function findIntegrators(mod) {
  const found = [];
  const seen = new Set();
  const candidates = [...(Array.isArray(mod.INTEGRATORS) ? mod.INTEGRATORS : []), ...Object.values(mod)];
  for (const c of candidates) {
    if (seen.has(c)) continue;
    seen.add(c);
    const it = integratorOf(c);
    if (it && it.name) found.push(it);
  }
  return found;
}

function sample(kind, k = 0) {
  const eye = () => [[1, 0, 0], [0, 1, 0], [0, 0, 1]];
  switch (kind) {
    case "T":
      return (3 + k) / 2;
    case "int":
      return 3;
    case "LieAlgebraId":
      return "so3";
    case "Vec3":
    case "VecX":
      return [2 + k, 3 / 2, 5 / 4];
    case "Vec6":
      return [0, 1, 2, 3, 4, 5].map((i) => (1 + i + k) / 2);
    case "Mat3":
    case "MatX":
      return [[2 + k, 0, 0], [0, 3, 0], [0, 0, 5]];
    case "RigidBodyState":
      return { Pi: sample("Vec3", 1), O: eye() };
    case "ManakovState":
      return { M: [[0, 1, -1], [-1, 0, 1 / 2], [1, -1 / 2, 0]], O: eye() };
    case "Vec3Pair":
      return [sample("Vec3", 1), sample("Vec3", 2)];
    case "MatXPair":
      return [eye(), sample("MatX", 1)];
  }
  if (kind.startsWith("EngineState:")) {
    const [, a, w, order] = kind.split(":");
    const att = a === "O" ? eye() : order === "quaternion_xyzw" ? [0, 0, 0, 1] : [1, 0, 0, 0];
    return { [a]: att, [w]: sample("Vec3", 1) };
  }
  throw new Error(kind);
}

// null when fn answers the probe arguments in double; else why not (kept available all the same: its
// error, with the stack, then shows in the properties that call it).
function probe(fn, sig, isStep) {
  try {
    const vals = sig[1].map((a, i) => sample(a, i));
    if (isStep) vals[vals.length - 1] = 1 / 64;
    encode(sig[0], fn(...vals));
    return null;
  } catch (e) {
    return "raises in double: " + firstLine(e);
  }
}

function answer(req, functions, steps) {
  const results = [];
  for (const call of req.calls || []) {
    const slot = call.slot;
    try {
      let fn, sig;
      if (call.integrator) {
        const key = call.integrator + "\u0000" + slot;
        fn = steps.fns.get(key);
        sig = steps.sigs.get(key) || STEP_SIGS[slot];
        if (!fn) throw new Error(`no integrator '${call.integrator}' with a ${slot}`);
      } else {
        [fn, sig] = functions.get(slot) || [];
        if (!fn) throw new Error(`no function named '${slot}'`);
      }
      if (call.scalar !== "double") throw new Error("JavaScript numbers are doubles: asked in " + call.scalar);
      const raw = [...(call.args || [])];
      const repeat = call.repeat;
      if (repeat === undefined || repeat === null) {
        results.push({ ok: encode(sig[0], fn(...sig[1].map((k, i) => decode(k, raw[i])))) });
        continue;
      }
      // A run of steps (docs/PROTOCOL.md): each step's state, encoded as its reply would be, is the
      // next step's argument, as if the harness had made the calls one by one.
      if (!call.integrator || !Number.isInteger(repeat) || repeat < 1 || raw.length !== 3)
        throw new Error('"repeat" needs an integrator\'s step, its three arguments and a count of at least 1');
      const states = [];
      for (let n = 0; n < repeat; n++) {
        raw[1] = encode(sig[0], fn(...sig[1].map((k, i) => decode(k, raw[i]))));
        states.push(raw[1]);
      }
      results.push({ ok: states });
    } catch (e) {
      results.push({ error: firstLine(e), traceback: studentTraceback(e) });
    }
  }
  return { id: req.id ?? null, results };
}

// Request lines read synchronously from stdin: a call's answer is written before the next is read.
function* requestLines() {
  const buf = Buffer.alloc(65536);
  let pending = "";
  for (;;) {
    let n;
    try {
      n = fs.readSync(0, buf, 0, buf.length, null);
    } catch (e) {
      if (e.code === "EAGAIN") continue;
      if (e.code === "EOF") return;
      throw e;
    }
    if (n === 0) {
      if (pending) yield pending;
      return;
    }
    pending += buf.toString("utf8", 0, n);
    let at;
    while ((at = pending.indexOf("\n")) >= 0) {
      yield pending.slice(0, at);
      pending = pending.slice(at + 1);
    }
  }
}

function serve(functions, steps) {
  for (const line of requestLines()) {
    if (!line.trim()) continue;  // the empty line after each request
    let req;
    try {
      req = JSON.parse(line);
    } catch (e) {
      reply({ fatal: "request is not JSON: " + e.message });
      continue;
    }
    if (req.session !== undefined) {
      reply({ id: req.id ?? null, fatal: "this server offers no sessions (\"sessions\": false in its handshake)" });
      continue;
    }
    reply(answer(req, functions, steps));
  }
  return 0;
}

async function load(file) {
  const mod = await import(pathToFileURL(path.resolve(file)).href);
  // CommonJS (module.exports = {...}, exports.hat = ...) arrives as the default export as well.
  const out = { ...mod };
  const d = mod.default;
  if (d != null && typeof d === "object" && !Array.isArray(d)) for (const [k, v] of Object.entries(d)) if (!(k in out)) out[k] = v;
  return out;
}

async function main() {
  const file = process.argv[2];
  if (process.argv.length !== 3) {
    reply({ fatal: "usage: node geomech_server.mjs FILE.mjs (or FILE.js)" });
    return 2;
  }
  const table = JSON.parse(process.env.GEOMECH_SLOT_TABLE || "{}");
  const sigs = new Map((table.slots || []).map((s) => [s.name, parseSignature(s.signature)]));
  for (const [k, v] of Object.entries(table.steps || {})) STEP_SIGS[k] = parseSignature(v);
  const probing = table.probe !== false;
  const doubleOnly = "JavaScript numbers are doubles (IEEE 754 binary64): a JavaScript implementation is checked in double only";
  const hello = {
    protocol: PROTOCOL, version: VERSION, language: "javascript", language_version: process.versions.node,
    interpreter: process.execPath, sessions: false, repeat: true,
    scalar_unavailable: { mp50: doubleOnly, exact: doubleOnly },
  };
  let mod;
  try {
    mod = await load(file);
  } catch (e) {
    reply({ ...hello, fatal: `importing ${file} failed:\n${studentTraceback(e)}` });
    return 1;
  }
  const functions = new Map();
  const warnings = [];
  for (const [name, sig] of sigs) {
    const fn = mod[name];
    if (typeof fn !== "function") continue;
    functions.set(name, [fn, sig]);
    const why = probing ? probe(fn, sig, false) : null;
    if (why) warnings.push(`slot '${name}' ${why} (with the harness's probe arguments)`);
  }
  const integrators = [];
  const steps = { fns: new Map(), sigs: new Map() };
  for (const it of findIntegrators(mod)) {
    const name = String(it.name);
    const declared = get(it.obj, "state");
    const isigs = {};
    if (declared != null && it.steps.includes("rigid_body_step") && stateKind(declared)) {
      const kind = stateKind(declared);
      isigs.rigid_body_step = [kind, ["Vec3", kind, "T"]];
    }
    const entry = { name, steps: it.steps, scalars: ["double"] };
    const claims = get(it.obj, "claims");
    if (claims != null && typeof claims === "object") entry.claims = { ...claims };
    if (declared != null) entry.state = inert(String(declared));
    for (const key of ["precision", "precision_reason"])
      if (get(it.obj, key) != null) entry[key] = inert(String(get(it.obj, key)));
    const domain = get(it.obj, "domain");
    if (domain != null && typeof domain === "object")
      entry.domain = Object.fromEntries(Object.entries(domain).map(([k, v]) => [k, Number(v)]));
    integrators.push(entry);
    for (const s of it.steps) {
      steps.fns.set(name + "\u0000" + s, it.obj[s]);
      steps.sigs.set(name + "\u0000" + s, isigs[s] || STEP_SIGS[s]);
    }
  }
  const slots = { double: [...functions.keys()], mp50: [], exact: [] };
  const notes = {};
  reply({
    ...hello, description: inert(mod.description ?? ""), slots, integrators, notes, warnings,
    mp50_bits: Number(table.mp50_bits || 168),
  });
  return serve(functions, steps);
}

// Exit when the input ends, whatever timers or handles the student's module left open.
process.exit(await main());
