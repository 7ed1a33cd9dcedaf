#!/usr/bin/env python3
"""geomech slot server for Python implementations (protocol: docs/PROTOCOL.md, version 2).

    python3 geomech_server.py mine.py
    python3 geomech_server.py week3.ipynb.json     (a notebook's code cells, written by the harness)

Imports mine.py (or runs a notebook's code cells in order, in one module, each under its own name:
"week3.ipynb, cell 4, In [3]" is the file name its tracebacks give, docs/PROTOCOL.md, "Notebooks"), finds the functions named after the harness's slots (the slot table comes from
the harness in $GEOMECH_SLOT_TABLE; `geomech slots --python` prints it for people), probes each in
the three scalars (float, mpmath.mpf at the harness's 50-digit precision, fractions.Fraction),
writes the handshake line, then answers one request line with one reply line until its input ends.
A request {"session": "begin"} forks a copy of this process that answers the calls of one check
and ends at {"session": "end"}; the server then goes on as the handshake left it.

Replies go to the descriptor $GEOMECH_REPLY_FD (3), so the student's print() can never be taken for
one; without it (by hand), to stdout, and print() goes to stderr.
"""
import importlib.util
import json
import linecache
import os
import sys
import traceback
import types
from fractions import Fraction

PROTOCOL = "geomech-slots"
VERSION = 2

try:
    import mpmath
    from mpmath.libmp import to_str as _mpf_to_str
except ImportError:  # pragma: no cover - mp50 is then unavailable
    mpmath = None

numpy = None  # set after the student's module is loaded, if it imported numpy (importing it costs ~0.2 s)

if os.environ.get("GEOMECH_REPLY_FD"):
    _out = os.fdopen(int(os.environ["GEOMECH_REPLY_FD"]), "w", buffering=1)
else:  # by hand: the protocol on stdout, the student's print() on stderr
    _out = sys.stdout
    sys.stdout = sys.stderr

MP_BITS = 168


class State(dict):
    """A state {"Pi": ..., "O": ...} (or {"M": ..., "O": ...}, or a declared form's {"q": ..., "omega": ...})
    read as x["Pi"] or x.Pi."""

    def __getattr__(self, k):
        try:
            return self[k]
        except KeyError:
            raise AttributeError(k)


class Inexact(Exception):
    pass


# ---- signatures ----------------------------------------------------------------------------------

def split_top(text):
    parts, depth, cur = [], 0, ""
    for ch in text:
        if ch in "<(":
            depth += 1
        elif ch in ">)":
            depth -= 1
        if ch == "," and depth == 0:
            parts.append(cur)
            cur = ""
        else:
            cur += ch
    if cur.strip():
        parts.append(cur)
    return parts


def kind_of(type_text):
    t = type_text.replace("const", "").replace("&", "").strip()
    t = t.split()[0] if t.split() else t
    if "<" in t:
        t = t[: t.index("<")]
    return t  # T, Vec3, Mat3, Vec6, VecX, MatX, int, LieAlgebraId, Vec3Pair, MatXPair, RigidBodyState, ...


def parse_signature(sig):
    """'Mat3<T>(const Vec3<T>& v)' -> ('Mat3', ['Vec3'])"""
    depth = 0
    for i, ch in enumerate(sig):
        if ch == "<":
            depth += 1
        elif ch == ">":
            depth -= 1
        elif ch == "(" and depth == 0:
            result = sig[:i]
            args = sig[i + 1: sig.rindex(")")]
            return kind_of(result), [kind_of(a) for a in split_top(args)]
    raise ValueError("bad signature " + sig)


# ---- numbers -------------------------------------------------------------------------------------

def make_scalar(scalar, text):
    if scalar == "double":
        if type(text) is str and "/" not in text:
            return float(text)
        return float(Fraction(text)) if "/" in str(text) else float(text)
    if scalar == "mp50":
        mpmath.mp.prec = MP_BITS
        if "/" in str(text):
            f = Fraction(text)
            return mpmath.mpf(f.numerator) / f.denominator
        return mpmath.mpf(text)
    return Fraction(text)


def decode(kind, scalar, v):
    if kind == "T":
        return make_scalar(scalar, v)
    if kind in ("int", "LieAlgebraId"):
        return v
    if kind in ("Vec3", "Vec6", "VecX"):
        return [make_scalar(scalar, x) for x in v]
    if kind in ("Mat3", "MatX"):
        return [[make_scalar(scalar, x) for x in row] for row in v]
    if kind == "RigidBodyState":
        return State(Pi=decode("Vec3", scalar, v["Pi"]), O=decode("Mat3", scalar, v["O"]))
    if kind == "ManakovState":
        return State(M=decode("MatX", scalar, v["M"]), O=decode("MatX", scalar, v["O"]))
    if kind.startswith("EngineState:"):  # a declared state form (docs/PROTOCOL.md, "State forms")
        a, w = kind.split(":")[1:3]
        return State({a: decode("Mat3" if a == "O" else "Vec4", scalar, v[a]), w: decode("Vec3", scalar, v[w])})
    if kind == "Vec4":
        return [make_scalar(scalar, x) for x in v]
    if kind in ("Vec3Pair", "MatXPair"):  # (Q, P) of the Clebsch steps: a 2-tuple
        part = "Vec3" if kind == "Vec3Pair" else "MatX"
        return (decode(part, scalar, v[0]), decode(part, scalar, v[1]))
    raise ValueError("unknown argument kind " + kind)


def encode_number(scalar, x):
    if type(x) is float and scalar == "double":  # the common case, first
        return repr(x)
    if isinstance(x, bool):
        raise TypeError("a bool where a number was expected")
    if isinstance(x, int):
        return str(x)
    if numpy is not None and isinstance(x, numpy.generic):
        if isinstance(x, numpy.integer):
            return str(int(x))
        x = float(x)
    if isinstance(x, Fraction):
        if scalar == "double":
            return repr(float(x))
        return "%d/%d" % (x.numerator, x.denominator)
    if mpmath is not None and isinstance(x, mpmath.mpf):
        if scalar == "exact":
            raise Inexact("an mpmath.mpf in an exact (Fraction) computation: the result is rounded, not exact")
        if scalar == "double":
            return repr(float(x))
        return _mpf_to_str(x._mpf_, 60)
    if isinstance(x, float):
        if scalar == "mp50":
            raise Inexact("a Python float in a 50-digit computation (math.sqrt, math.cos, numpy or a float "
                          "literal like 0.5 round to double precision); write generic code, e.g. x / 2")
        if scalar == "exact":
            raise Inexact("a Python float in an exact (Fraction) computation (math.sqrt, numpy or a float "
                          "literal like 0.5 make the result inexact)")
        return repr(x)
    if mpmath is not None and isinstance(x, mpmath.mpc):
        raise TypeError("a complex number where a real was expected")
    if isinstance(x, complex):
        raise TypeError("a complex number where a real was expected")
    try:
        return repr(float(x)) if scalar == "double" else str(x)
    except Exception:
        raise TypeError("not a number: %r" % (x,))


def encode(kind, scalar, x):
    if numpy is not None and isinstance(x, numpy.ndarray):
        x = x.tolist()
    if kind == "T":
        return encode_number(scalar, x)
    if kind in ("Vec3", "Vec4", "Vec6", "VecX"):
        seq = list(x)
        if seq and numpy is not None and isinstance(seq[0], numpy.ndarray):
            seq = [e.tolist() for e in seq]
        # a column vector written as a list of 1-lists is accepted
        if seq and all(isinstance(e, (list, tuple)) and len(e) == 1 for e in seq):
            seq = [e[0] for e in seq]
        return [encode_number(scalar, e) for e in seq]
    if kind in ("Mat3", "MatX"):
        out = []
        for row in x:
            if numpy is not None and isinstance(row, numpy.ndarray):
                row = row.tolist()
            out.append([encode_number(scalar, e) for e in row])
        return out
    if kind == "Vec3Pair":
        a, b = x
        return [encode("Vec3", scalar, a), encode("Vec3", scalar, b)]
    if kind == "MatXPair":
        a, b = x
        return [encode("MatX", scalar, a), encode("MatX", scalar, b)]
    if kind.startswith("EngineState:"):  # the declared keys: a dict, an object with them, or (attitude, angular)
        a, w = kind.split(":")[1:3]
        if isinstance(x, dict):
            xa, xw = x[a], x[w]
        elif hasattr(x, a):
            xa, xw = getattr(x, a), getattr(x, w)
        else:
            xa, xw = x
        return {a: encode("Mat3" if a == "O" else "Vec4", scalar, xa), w: encode("Vec3", scalar, xw)}
    if kind in ("RigidBodyState", "ManakovState"):
        keys = ("Pi", "O") if kind == "RigidBodyState" else ("M", "O")
        vk = "Vec3" if kind == "RigidBodyState" else "MatX"
        mk = "Mat3" if kind == "RigidBodyState" else "MatX"
        if isinstance(x, dict):
            a, b = x[keys[0]], x[keys[1]]
        elif hasattr(x, keys[0]):
            a, b = getattr(x, keys[0]), getattr(x, keys[1])
        else:
            a, b = x
        return {keys[0]: encode(vk, scalar, a), keys[1]: encode(mk, scalar, b)}
    raise ValueError("unknown result kind " + kind)


# ---- the student's module ------------------------------------------------------------------------

class CellFailed(Exception):
    """A notebook cell that raised when run: its name ("week3.ipynb, cell 4, In [3]") and the error."""

    def __init__(self, name, error):
        Exception.__init__(self, name)
        self.name, self.error = name, error


def display(*objs, **kwargs):
    """Jupyter's display(), which IPython puts in a notebook's namespace: IPython's own when it is
    installed, else each object's repr on stderr (a check shows nothing)."""
    try:
        from IPython.display import display as shown
    except ImportError:
        for obj in objs:
            print(repr(obj), file=sys.stderr)
        return None
    return shown(*objs, **kwargs)


def load_cells(path):
    """A notebook's code cells (the cells file the harness wrote from it), run in order in one module,
    as Jupyter's kernel runs them. Each is compiled under its own name, which tracebacks give as the
    file (with its lines, through linecache); the first to raise stops the loading (CellFailed)."""
    with open(path, encoding="utf-8") as f:
        cells = json.load(f)
    mod = types.ModuleType("student_impl", None)
    mod.__file__ = cells.get("notebook", path)
    mod.display = display
    folder = cells.get("folder") or os.path.dirname(os.path.abspath(path))
    sys.path.insert(0, folder)
    os.environ.setdefault("MPLBACKEND", "Agg")  # a plot in a cell draws nothing and opens no window
    for cell in cells.get("cells", []):
        name, code = cell["name"], cell["code"]
        linecache.cache[name] = (len(code), None, code.splitlines(True), name)
        try:
            exec(compile(code, name, "exec"), mod.__dict__)
        except BaseException as e:
            raise CellFailed(name, e)
    return mod


def load(path):
    if path.endswith(".json"):
        return load_cells(path)
    spec = importlib.util.spec_from_file_location("student_impl", path)
    mod = importlib.util.module_from_spec(spec)
    sys.path.insert(0, os.path.dirname(os.path.abspath(path)))
    spec.loader.exec_module(mod)
    return mod


def inert(text):
    """Text from the student's code as it may travel and be shown: a lone surrogate (from
    bytes decoded with surrogateescape, or '\\udcff' written in a string), which json.dumps would
    send as an escape no UTF-8 reader accepts, becomes the visible text \\udcff. Control characters
    are made visible on the harness's side, where every report is written."""
    if not isinstance(text, str):
        text = repr(text)
    return text.encode("utf-8", "backslashreplace").decode("utf-8")


def student_traceback(exc):
    """The traceback without the server's own frames."""
    tb = exc.__traceback__
    while tb is not None and tb.tb_frame.f_code.co_filename == __file__:
        tb = tb.tb_next
    return inert("".join(traceback.format_exception(type(exc), exc, tb)).rstrip())


def get(obj, key, default=None):
    if isinstance(obj, dict):
        return obj.get(key, default)
    return getattr(obj, key, default)


def state_kind(words):
    """The argument kind of a rigid-body step kept in a declared form ("quaternion_wxyz omega"):
    EngineState:<attitude key>:<angular key>:<attitude word>. The harness checks the words."""
    w = str(words).replace(",", " ").split()
    if len(w) != 2:
        return None
    return "EngineState:%s:%s:%s" % ("O" if w[0] == "matrix" else "q", w[1], w[0])


def find_integrators(mod):
    found = []
    seen = set()
    candidates = list(getattr(mod, "INTEGRATORS", []) or [])
    for k, v in vars(mod).items():
        if k.startswith("_"):
            continue
        if isinstance(v, type) and getattr(v, "__module__", None) != mod.__name__:
            continue
        if isinstance(v, (type, dict)) or (not callable(v) and hasattr(v, "__dict__")):
            candidates.append(v)
    for c in candidates:
        if id(c) in seen:
            continue
        seen.add(id(c))
        steps = [s for s in STEP_SIGS if callable(get(c, s))]
        if not steps or not get(c, "name"):
            continue
        found.append((str(get(c, "name")), c, steps))
    return found


def sample(kind, scalar, k=0):
    """Arguments for probing: consistent shapes (VecX of length 3, MatX 3 x 3, n = 3, so3)."""
    f = lambda p, q=1: make_scalar(scalar, "%d/%d" % (p, q))
    if kind == "T":
        return f(3 + k, 2)
    if kind == "int":
        return 3
    if kind == "LieAlgebraId":
        return "so3"
    if kind == "Vec3" or kind == "VecX":
        return [f(2 + k), f(3, 2), f(5, 4)]
    if kind == "Vec6":
        return [f(1 + i + k, 2) for i in range(6)]
    if kind == "Mat3" or kind == "MatX":
        return [[f(2 + k), f(0), f(0)], [f(0), f(3), f(0)], [f(0), f(0), f(5)]]
    if kind == "RigidBodyState":
        return State(Pi=sample("Vec3", scalar, 1), O=[[f(1 if i == j else 0) for j in range(3)] for i in range(3)])
    if kind.startswith("EngineState:"):
        a, w, order = kind.split(":")[1:4]
        att = [[f(1 if i == j else 0) for j in range(3)] for i in range(3)] if a == "O" else \
            ([f(0), f(0), f(0), f(1)] if order == "quaternion_xyzw" else [f(1), f(0), f(0), f(0)])
        return State({a: att, w: sample("Vec3", scalar, 1)})
    if kind == "ManakovState":
        M = [[f(0), f(1), f(-1)], [f(-1), f(0), f(1, 2)], [f(1), f(-1, 2), f(0)]]
        return State(M=M, O=[[f(1 if i == j else 0) for j in range(3)] for i in range(3)])
    if kind == "Vec3Pair":
        return (sample("Vec3", scalar, 1), sample("Vec3", scalar, 2))
    if kind == "MatXPair":
        return ([[f(1 if i == j else 0) for j in range(3)] for i in range(3)], sample("MatX", scalar, 1))
    raise ValueError(kind)


# The integrator steps (the harness's slot table replaces these with its own list).
STEP_SIGS = {
    "rigid_body_step": ("RigidBodyState", ["Vec3", "RigidBodyState", "T"]),
    "manakov_step": ("ManakovState", ["MatX", "ManakovState", "T"]),
    "clebsch_step": ("Vec3Pair", ["Vec3", "Vec3Pair", "T"]),
    "manakov_clebsch_step": ("MatXPair", ["MatX", "MatXPair", "T"]),
}


def probe(fn, sig, scalar):
    """None when fn works in this scalar; ("inexact", why) when its result is not of this scalar (a
    float where an mpf or a Fraction is asked: the code computes in double only); ("raised", why)
    when it raises. Only the first leaves the slot out of the scalar: an exception is the slot's own
    failure there, and its checks show it with the traceback (a TypeError in 50-digit code was once
    read as "not provided")."""
    result, args = sig
    try:
        vals = [sample(a, scalar, i) for i, a in enumerate(args)]
        if sig in STEP_SIGS.values() or sig[0].startswith("EngineState:"):  # a step: a small h
            vals[-1] = make_scalar(scalar, "1/64")
        encode(result, scalar, fn(*vals))
        return None
    except Inexact as e:
        return ("inexact", str(e))
    except Exception as e:
        tb = student_traceback(e).splitlines()
        return ("raised", "raises in %s: %s" % ({"double": "float", "mp50": "mpmath.mpf", "exact": "Fraction"}[scalar],
                                               tb[-1] if tb else inert(repr(e))))


class Lines:
    """Request lines read from a descriptor without a stdio buffer: a session's copy made by fork
    takes over the same input, and the server resumes after it without losing a byte."""

    def __init__(self, fd):
        self.fd = fd
        self.buf = b""

    def next(self):
        while b"\n" not in self.buf:
            chunk = os.read(self.fd, 65536)
            if not chunk:
                return None
            self.buf += chunk
        line, self.buf = self.buf.split(b"\n", 1)
        return line.decode("utf-8", "replace")


def reply(obj):
    # Straight to the descriptor: a text stream's write and flush cost more than the call itself for
    # most slots (docs/PERFORMANCE.md). Every other write to _out is flushed at once, so nothing of
    # it can be left behind in its buffer.
    data = (json.dumps(obj) + "\n").encode()
    fd = _out.fileno()
    while data:
        data = data[os.write(fd, data):]


def how_it_ended(status):
    if os.WIFSIGNALED(status):
        import signal
        try:
            name = signal.Signals(os.WTERMSIG(status)).name
        except ValueError:
            name = str(os.WTERMSIG(status))
        return "was killed by signal %s" % name
    if os.WIFEXITED(status):
        return "exited with status %d (sys.exit or os._exit in the implementation?)" % os.WEXITSTATUS(status)
    return "ended"


def answer(req, functions, steps):
    results = []
    for call in req.get("calls", []):
        slot, scalar = call.get("slot"), call.get("scalar")
        try:
            if call.get("integrator"):
                fn = steps[0].get((call["integrator"], slot))
                sig = steps[1].get((call["integrator"], slot), STEP_SIGS.get(slot))
                if fn is None:
                    raise LookupError("no integrator %r with a %s" % (call["integrator"], slot))
            else:
                fn, sig = functions.get(slot, (None, None))
                if fn is None:
                    raise LookupError("no function named %r" % slot)
            raw = list(call.get("args", []))
            repeat = call.get("repeat")
            if repeat is None:
                args = [decode(k, scalar, a) for k, a in zip(sig[1], raw)]
                results.append({"ok": encode(sig[0], scalar, fn(*args))})
                continue
            # A run of steps (docs/PROTOCOL.md): each step's state, encoded as its reply would be, is
            # the next step's argument, as if the harness had made the calls one by one.
            if not call.get("integrator") or not isinstance(repeat, int) or repeat < 1 or len(raw) != 3:
                raise ValueError("\"repeat\" needs an integrator's step, its three arguments and a count of at least 1")
            states = []
            for _ in range(repeat):
                args = [decode(k, scalar, a) for k, a in zip(sig[1], raw)]
                raw[1] = encode(sig[0], scalar, fn(*args))
                states.append(raw[1])
            results.append({"ok": states})
        except Inexact as e:
            results.append({"error": inert("%s returned %s" % (slot, e))})
        except SystemExit as e:
            results.append({"error": "%s called sys.exit(%r): a slot function must return its value" % (slot, e.code)})
        except Exception as e:
            tb = student_traceback(e)
            results.append({"error": tb.splitlines()[-1] if tb else inert(repr(e)), "traceback": tb})
    return {"id": req.get("id"), "results": results}


def start_profile():
    """$GEOMECH_PROFILE=dir: each session's time by function (cProfile), written to
    dir/session-PID.prof when the session ends, for finding where a check's time goes
    (python3 -m pstats dir/session-PID.prof). Off unless set."""
    where = os.environ.get("GEOMECH_PROFILE")
    if not where:
        return None
    import cProfile
    profile = cProfile.Profile()
    profile.enable()
    return (profile, where)


def stop_profile(profile):
    if profile:
        profile[0].disable()
        profile[0].dump_stats(os.path.join(profile[1], "session-%d.prof" % os.getpid()))


def serve(lines, functions, steps, in_session):
    """Answers requests until the input ends (0) or, in a session, until {"session": "end"} (1)."""
    while True:
        line = lines.next()
        if line is None:
            return 0
        if not line.strip():
            continue  # the empty line after each request
        try:
            req = json.loads(line)
        except ValueError as e:
            reply({"fatal": "request is not JSON: %s" % e})
            continue
        what = req.get("session")
        if what == "end" and in_session:
            reply({"id": req.get("id"), "session": "ended"})
            return 1
        if what == "begin" and not in_session:
            done_r, done_w = os.pipe()
            pid = os.fork()
            if pid == 0:
                os.close(done_r)
                reply({"id": req.get("id"), "session": "begun", "pid": os.getpid()})
                profile = start_profile()
                if serve(lines, functions, steps, in_session=True) == 1:
                    stop_profile(profile)
                    os.write(done_w, b"E")
                _out.flush()
                os._exit(0)
            os.close(done_w)
            _, status = os.waitpid(pid, 0)
            ended = os.read(done_r, 1) == b"E" and os.WIFEXITED(status) and os.WEXITSTATUS(status) == 0
            os.close(done_r)
            if not ended:  # it died in the session: the harness is waiting for a reply
                reply({"id": None, "died": how_it_ended(status)})
            continue
        if what is not None:
            reply({"id": req.get("id"), "fatal": "unexpected session request %r" % what})
            continue
        reply(answer(req, functions, steps))


def main():
    global MP_BITS
    if len(sys.argv) != 2:
        _out.write(json.dumps({"fatal": "usage: geomech_server.py FILE.py (or a notebook's CELLS.json)"}) + "\n")
        return 2
    table = json.loads(os.environ.get("GEOMECH_SLOT_TABLE", "{}") or "{}")
    MP_BITS = int(table.get("mp50_bits", 168))
    sigs = {s["name"]: parse_signature(s["signature"]) for s in table.get("slots", [])}
    for k, v in table.get("steps", {}).items():
        STEP_SIGS[k] = parse_signature(v)
    scalars = ["double", "mp50", "exact"] if mpmath is not None else ["double", "exact"]
    warnings = []
    unavailable = {}
    if mpmath is None:
        # Say which interpreter lacks it, and how to choose another.
        why = ("mpmath cannot be imported by %s (Python %s), the interpreter that runs your file, so nothing is "
               "checked in 50 digits: install mpmath for that interpreter (Debian's /usr/bin/python3: apt-get install "
               "python3-mpmath; a venv: its pip), or set GEOMECH_PYTHON to an interpreter that has it"
               % (sys.executable, sys.version.split()[0]))
        warnings.append(why)
        unavailable["mp50"] = why
    elif getattr(mpmath.libmp, "BACKEND", "gmpy") != "gmpy":
        # Mpmath without gmpy2 computes with Python's own integers: said, with what it cost
        # where it was measured and the one command that fixes it.
        warnings.append(
            "mpmath in %s (Python %s) runs without gmpy2, on its pure-Python backend: the 50-digit checks take "
            "longer (examples/students/correct.py's: 1.07x with Debian's python3; more on an interpreter built "
            "without optimisations); install gmpy2 for that interpreter (Debian's /usr/bin/python3: apt-get install "
            "python3-gmpy2; a venv or pyenv: its pip install gmpy2), or set GEOMECH_PYTHON to one that has it"
            % (sys.executable, sys.version.split()[0]))
    try:
        mod = load(sys.argv[1])
    except BaseException as e:
        what = "importing %s failed" % sys.argv[1]
        if isinstance(e, CellFailed):  # the student's cell, named as the notebook shows it
            what, e = "%s failed when run (the cells before it ran)" % e.name, e.error
        hint = ""
        if isinstance(e, ImportError):  # Which interpreter, and how to choose another
            hint = ("\n(the interpreter running it is %s, Python %s: a module the file imports is not installed for it; "
                    "install it there, or set GEOMECH_PYTHON to an interpreter that has it)"
                    % (sys.executable, sys.version.split()[0]))
        _out.write(json.dumps({"protocol": PROTOCOL, "version": VERSION, "language": "python",
                               "fatal": "%s:\n%s%s" % (what, student_traceback(e), hint)}) + "\n")
        _out.flush()
        return 1

    global numpy
    numpy = sys.modules.get("numpy")
    functions = {}
    slots = {s: [] for s in scalars}
    notes = {}
    for name, sig in sigs.items():
        fn = getattr(mod, name, None)
        if fn is None or not callable(fn):
            continue
        functions[name] = (fn, sig)
        # A function that fails even in float is kept in every scalar: its error (with the
        # traceback) then shows in the properties that call it. One that works in float but not in
        # mpf or Fraction is checked only where it works, and the report says why.
        base = probe(fn, sig, "double") if table.get("probe", True) else None
        if base is not None:
            warnings.append("slot '%s' %s (with the harness's probe arguments)" % (name, base[1]))
        for scalar in scalars:
            why = None if (base is not None or scalar == "double" or not table.get("probe", True)) \
                else probe(fn, sig, scalar)
            if why is None or why[0] == "raised":
                slots[scalar].append(name)
            else:
                notes.setdefault(scalar, {})[name] = why[1]
    integrators = []
    steps = {}
    step_sigs = {}
    for iname, obj, isteps in find_integrators(mod):
        iscalars = []
        # A rigid-body step kept in a declared form (docs/PROTOCOL.md, "State forms"): its state
        # argument and result are that form's keys; the harness converts.
        declared = get(obj, "state", None)
        isigs = {}
        if declared is not None and "rigid_body_step" in isteps and state_kind(declared):
            kind = state_kind(declared)
            isigs["rigid_body_step"] = (kind, ["Vec3", kind, "T"])
        for scalar in ("double", "mp50"):
            if scalar not in scalars:
                continue
            ok = True
            precision = get(obj, "precision", None)
            if precision is not None and str(precision) in ("double", "float", "single") and scalar != "double":
                # A stated precision: run in double only (a float step driven in 50 digits computes in
                # float all the same), judged at that precision's eps, and say why in the report.
                why = get(obj, "precision_reason", None)
                for s in isteps:
                    notes.setdefault(scalar, {})["%s.%s" % (iname, s)] = "computes in %s (%s)" % (
                        inert(str(precision)), "stated: " + inert(str(why)) if why else "stated, without a reason")
                continue
            for s in (isteps if table.get("probe", True) and scalar != "double" else []):
                sig = isigs.get(s, STEP_SIGS[s])
                why = probe(get(obj, s), sig, scalar)
                if why is not None and why[0] == "inexact" and probe(get(obj, s), sig, "double") is None:
                    ok = False
                    notes.setdefault(scalar, {})["%s.%s" % (iname, s)] = why[1]
            if ok:
                iscalars.append(scalar)
        claims = get(obj, "claims", None)
        entry = {"name": iname, "steps": isteps, "scalars": iscalars}
        if claims:
            entry["claims"] = dict(claims)
        if declared is not None:
            entry["state"] = inert(str(declared))
        for key in ("precision", "precision_reason"):
            if get(obj, key, None) is not None:
                entry[key] = inert(str(get(obj, key)))
        domain = get(obj, "domain", None)  # where the step is meant to work
        if domain:
            entry["domain"] = {k: float(v) for k, v in dict(domain).items()}
        integrators.append(entry)
        for s in isteps:
            steps[(iname, s)] = get(obj, s)
            step_sigs[(iname, s)] = isigs.get(s, STEP_SIGS[s])
    description = inert(getattr(mod, "description", None) or ((mod.__doc__ or "").strip().splitlines() or [""])[0])
    hello = {"protocol": PROTOCOL, "version": VERSION, "language": "python",
             "language_version": sys.version.split()[0], "interpreter": sys.executable, "description": description,
             "slots": slots, "integrators": integrators, "notes": notes, "warnings": warnings,
             "mp50_bits": MP_BITS, "sessions": hasattr(os, "fork"), "repeat": True}
    if unavailable:
        hello["scalar_unavailable"] = unavailable
    _out.write(json.dumps(hello) + "\n")
    _out.flush()

    return serve(Lines(0), functions, (steps, step_sigs), in_session=False)


if __name__ == "__main__":
    sys.exit(main())
