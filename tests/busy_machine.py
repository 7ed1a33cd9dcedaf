"""Slow is judged by the work done, not by the clock of a busy machine (a machine fault is not graded).

    python3 busy_machine.py GEOMECH OUT_DIR

A correct implementation's costly check is run alone, then with the machine loaded sixteen times
over (busy loops, sixteen per core: 32 on 2 cores), with the same options: a time budget for its cases and a timeout set
so that alone it runs all its cases well within both. On a busy machine its wall clock runs past
both; the budget and the timeout count the CPU time of the code under test, and a task the
kernel's run queue holds (schedstat's run_delay) is starved, not waiting, and is let run: the
check must end with the same verdict and the same number of cases. Control: the loaded run really was starved (its wall clock at least twice its CPU), the
condition in which a wall-clock budget cut cases and a wall-clock timeout reported a TIMEOUT for
correct code.
"""
import json
import multiprocessing
import os
import shutil
import subprocess
import sys
import time

GEOMECH, OUT = sys.argv[1:3]
# The reference's 50-digit check of the Hamilton-Pontryagin variation on SO(n): about 0.65 s of CPU
# a case (1.3 s for the two, 2026-11-29), long enough for the kernel's accounting, which the check
# reads four times a second, to see each case starved for seconds. Until 2026-11-29 it was Manakov's
# Clebsch momentum, 1.4 s a case: the loaded run alone took about 50 s of a ctest run in which
# nothing else may run beside this test.
CHECK = ["check", "--subject", "reference", "-p", "hamilton_pontryagin_variation_so_n", "--scalar", "mp50",
         "--cases", "2", "-j", "1"]


def run(tag, timeout, budget):
    report = os.path.join(OUT, tag)
    start = time.time()
    cpu0 = os.times()
    p = subprocess.run([GEOMECH] + CHECK + ["--timeout", str(timeout), "--case-budget", str(budget), "--report", report],
                       capture_output=True, text=True, errors="replace", timeout=3600)
    wall = time.time() - start
    cpu1 = os.times()
    cpu = (cpu1.children_user - cpu0.children_user) + (cpu1.children_system - cpu0.children_system)
    v = json.load(open(os.path.join(report, "verdicts.json")))["verdicts"][0]
    return v, wall, cpu, p.stdout + p.stderr


def burn():
    while True:
        pass


shutil.rmtree(OUT, ignore_errors=True)
os.makedirs(OUT)
alone, wall_alone, cpu_alone, out_alone = run("alone", 600, 0)
print("alone: %s, %d of %d cases, %.1f s wall, %.1f s CPU" % (alone["outcome"], alone["cases"], alone["cases_planned"], wall_alone, cpu_alone))
if alone["outcome"] != "PASS" or alone["cases"] != alone["cases_planned"]:
    sys.exit("alone, the reference should pass every planned case:\n" + out_alone[-3000:])
# The budget and the timeout: twice and three times the CPU the check needs alone, so that alone
# there is room, and a wall clock four or more times slower would run past them.
budget = max(2.0, 2 * cpu_alone)
timeout = max(3.0, 3 * cpu_alone)
base, _, _, out_base = run("alone-budget", timeout, budget)
loaders = [multiprocessing.Process(target=burn, daemon=True) for _ in range(16 * (os.cpu_count() or 2))]
for l in loaders:
    l.start()
try:
    loaded, wall_loaded, cpu_loaded, out_loaded = run("loaded", timeout, budget)
finally:
    for l in loaders:
        l.terminate()
print("loaded x16: %s, %d of %d cases, %.1f s wall, %.1f s CPU (budget %.1f s, timeout %.1f s of CPU)"
      % (loaded["outcome"], loaded["cases"], loaded["cases_planned"], wall_loaded, cpu_loaded, budget, timeout))
problems = []
if wall_loaded < 2 * cpu_loaded:
    problems.append("control: the loaded run was not starved (%.1f s wall for %.1f s CPU): the test shows nothing" % (wall_loaded, cpu_loaded))
if wall_loaded < budget:
    problems.append("control: the loaded run's wall clock (%.1f s) did not pass the budget (%.1f s)" % (wall_loaded, budget))
for k in ("outcome", "cases", "cases_planned"):
    if loaded[k] != base[k]:
        problems.append("%s differs: %r alone against %r loaded\n--- loaded:\n%s" % (k, base[k], loaded[k], out_loaded[-3000:]))
if problems:
    sys.exit("\n".join(problems))
print("the same verdict and cases on a machine loaded sixteen times over")
