"""An engine shaped like a library, checked with no flag written by hand (its // geomech: lines suffice).

    python3 library_shaped.py GEOMECH OUT

The test builds, in OUT/root, a library as a researcher's engine is installed: a header, a static
library, and a pkg-config file whose --cflags carry `-std=c++11` (as a dependency's .pc may) and
which `Requires:` a second library (its header's inline code calls it: a transitive library). A
file using the engine says `// geomech: pkg fakeengine` and nothing else. It is checked
  - trusted:   the suite drops -std=c++11 (said under --verbose), links both libraries, passes;
  - untrusted, the engine's folder not trusted: refused, the refusal naming the folder and
               GEOMECH_LIBRARY_ROOTS (never a compile error);
  - untrusted, GEOMECH_LIBRARY_ROOTS=OUT/root: the sandboxed build reads the engine there, passes.
The engine computes the energy (3.4) itself, so the check's verdict is the engine's: its control is
the same file with the engine's energy off by a factor 2, which must FAIL in both modes, and
every replay command it prints, run as printed, must FAIL again.
"""
import os
import re
import shlex
import shutil
import subprocess
import sys

GEOMECH, OUT = sys.argv[1:3]
failures = []


def check(cond, what):
    if not cond:
        failures.append(what)


def run(args, env_extra, timeout=900):
    env = dict(os.environ)
    env.update(env_extra)
    p = subprocess.run([GEOMECH] + args, capture_output=True, text=True, errors="replace", timeout=timeout, env=env)
    return p.returncode, p.stdout + p.stderr


shutil.rmtree(OUT, ignore_errors=True)
root = os.path.join(OUT, "root")
for d in ("include/fakeengine", "include/fakemath", "lib/pkgconfig", "src"):
    os.makedirs(os.path.join(root, d))
os.chmod(OUT, 0o755)


def write(rel, text):
    with open(os.path.join(root, rel), "w") as f:
        f.write(text)


write("include/fakemath/fm.hpp", "#pragma once\ndouble fm_weighted_dot(const double* a, const double* b, const double* w);\n")
write("src/fm.cpp", '#include <fakemath/fm.hpp>\n'
      'double fm_weighted_dot(const double* a, const double* b, const double* w) {\n'
      '  return a[0] * b[0] * w[0] + a[1] * b[1] * w[1] + a[2] * b[2] * w[2];\n}\n')


def engine_header(factor):
    return ("#pragma once\n#include <fakemath/fm.hpp>\n"
            "// The engine's energy Pi . I^-1 Pi / 2, inline: a user of this header links fakemath too.\n"
            "inline double fe_energy(const double I[3], const double Pi[3]) {\n"
            "  const double inv[3] = {1 / I[0], 1 / I[1], 1 / I[2]};\n"
            "  return fm_weighted_dot(Pi, Pi, inv) / %s;\n}\n" % factor)


write("include/fakeengine/engine.hpp", engine_header("2"))
write("lib/pkgconfig/fakemath.pc", "prefix=%s\nincludedir=${prefix}/include\nlibdir=${prefix}/lib\n\n"
      "Name: fakemath\nDescription: a library the engine needs\nVersion: 1.0\n"
      "Cflags: -I${includedir} -O2 -Wall\nLibs: -L${libdir} -lfakemath\n" % root)
write("lib/pkgconfig/fakeengine.pc", "prefix=%s\nincludedir=${prefix}/include\nlibdir=${prefix}/lib\n\n"
      "Name: fakeengine\nDescription: an engine shaped like a library\nVersion: 1.0\nRequires: fakemath\n"
      "Cflags: -std=c++11 -I${includedir}\nLibs: -L${libdir}\n" % root)
obj = os.path.join(root, "src", "fm.o")
subprocess.run(["c++", "-std=c++11", "-O2", "-fPIC", "-I" + os.path.join(root, "include"), "-c",
                os.path.join(root, "src", "fm.cpp"), "-o", obj], check=True)
subprocess.run(["ar", "rcs", os.path.join(root, "lib", "libfakemath.a"), obj], check=True)
for dirpath, dirs, files in os.walk(OUT):  # the sandbox's user reads what the lecturer installed
    for d in dirs:
        os.chmod(os.path.join(dirpath, d), 0o755)
    for f in files:
        os.chmod(os.path.join(dirpath, f), 0o644)

student = os.path.join(OUT, "engine_energy.cpp")
with open(student, "w") as f:
    f.write("// The energy (3.4) through an engine installed as a library.\n"
            "// geomech: pkg fakeengine\n"
            "#include <geomech/student.hpp>\n#include <fakeengine/engine.hpp>\n\n"
            "struct EngineEnergy {\n"
            "  static double hamiltonian_3_4(const gm::Vec3<double>& I, const gm::Vec3<double>& Pi) {\n"
            "    const double i[3] = {I(0), I(1), I(2)}, p[3] = {Pi(0), Pi(1), Pi(2)};\n"
            "    return fe_energy(i, p);\n  }\n};\n\nGEOMECH_STUDENT(EngineEnergy);\n")
os.chmod(student, 0o644)
env = {"PKG_CONFIG_PATH": os.path.join(root, "lib", "pkgconfig")}
prop = ["-p", "definition_hamiltonian_3_4", "--scalar", "double"]
replayed = []


def verdict(console):
    for line in console.splitlines():
        if line.startswith("definition_hamiltonian_3_4"):
            return line
    return ""


# Trusted: nothing written by hand, -std=c++11 left out and said so.
rc, console = run(["check", student, "--verbose", "--cache-dir", os.path.join(OUT, "cache")] + prop, env)
check(rc == 0 and "PASS" in verdict(console), "trusted: the engine's energy should PASS (exit %d):\n%s" % (rc, console[-3000:]))
check("-std=c++11" in console and "left out" in console, "trusted: --verbose should say -std=c++11 was left out")

# Untrusted, the engine's folder not trusted: a refusal naming it and the setting, not a compile error.
rc, console = run(["check", student, "--untrusted", "--cache-dir", os.path.join(OUT, "cache-u")] + prop, env)
check(rc == 2 and "GEOMECH_LIBRARY_ROOTS" in console and os.path.join(root, "include") in console
      and "does not compile" not in console,
      "untrusted without the root: a refusal naming the folder and GEOMECH_LIBRARY_ROOTS (exit %d):\n%s" % (rc, console[-3000:]))

# Untrusted, the lecturer trusts the engine's folder.
env_root = dict(env, GEOMECH_LIBRARY_ROOTS=root)
rc, console = run(["check", student, "--untrusted", "--cache-dir", os.path.join(OUT, "cache-u")] + prop, env_root)
check(rc == 0 and "PASS" in verdict(console), "untrusted with the root: the engine's energy should PASS (exit %d):\n%s" % (rc, console[-3000:]))

# The control: the engine off by a factor 2 fails in both modes (the verdict is the engine's).
write("include/fakeengine/engine.hpp", engine_header("4"))
for mode, extra, e in (("trusted", [], env), ("untrusted", ["--untrusted"], env_root)):
    rc, console = run(["check", student, "--cache-dir", os.path.join(OUT, "cache-" + mode)] + extra + prop, e)
    check(rc == 1 and "FAIL" in verdict(console), "%s control: an engine off by 2 should FAIL (exit %d):\n%s" % (mode, rc, console[-3000:]))
    # The replay command printed, run as printed in the same shell (no flag added), fails again.
    replays = sorted({line.split("reproduce:", 1)[1].strip() for line in console.splitlines() if "reproduce:" in line})
    check(len(replays) > 0, "%s control: no replay command printed:\n%s" % (mode, console[-3000:]))
    replayed.extend(replays)
    for replay in replays:
        # The command names the tool as its user called it ("geomech", "./geomech"): here, the one under test.
        replay = re.sub(r"^\S*geomech ", lambda m: shlex.quote(GEOMECH) + " ", replay, count=1)
        p = subprocess.run(["sh", "-c", replay], capture_output=True, text=True, errors="replace", timeout=900,
                           env=dict(os.environ, **e))
        check(p.returncode == 1 and "FAIL" in verdict(p.stdout + p.stderr),
              "%s control: the replay command did not fail again (exit %d):\n%s\n%s" % (mode, p.returncode, replay,
                                                                                           (p.stdout + p.stderr)[-3000:]))

if failures:
    print("\n\n".join("FAILED: " + f for f in failures))
    sys.exit(1)
print("a library-shaped engine is checked trusted and untrusted with no flag written by hand; %d replay commands "
      "run as printed failed again:\n%s" % (len(replayed), "\n".join(replayed)))
