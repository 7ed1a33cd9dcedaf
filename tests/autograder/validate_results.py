#!/usr/bin/env python3
"""Validates a results.json against the format its platform documents (Gradescope, PrairieLearn).

  validate_results.py gradescope FILE     Gradescope's autograder output
  validate_results.py prairielearn FILE   PrairieLearn's external grader results
  validate_results.py --self-test         the negative controls: documents that break each rule must
                                          be refused, and the documented examples accepted

Gradescope (gradescope/autograder_samples, docs/specs.md, "Output format"): top-level keys score,
execution_time, output, output_format, test_output_format, test_name_format, visibility,
stdout_visibility, extra_data, tests, leaderboard; score is required unless every test has one;
each test may have score, max_score, status ("passed" or "failed"), name, name_format, number,
output, output_format, tags, visibility, extra_data; visibility is one of hidden, after_due_date,
after_published, visible; a format one of text, html, simple_format, md, ansi. Outputs use Unix line
ends.

PrairieLearn (PrairieLearn/PrairieLearn, docs/externalGrading.md, "Grading results"): when gradable,
score is required and a number in [0, 1]; gradable is a boolean (absent means true); format_errors a
string or a list of strings; message and output strings; images a list of {url, label} or strings;
tests a list of objects with name, description, points, max_points, message, output, images; the
file at most 1 MB.

Beyond the formats, what the suite promises (checked here too): a score never exceeds its maximum,
the tests' scores add up to the top-level score (to 0.01 per test of rounding), no key outside the
documented ones.
"""
import json
import sys

VISIBILITY = {"hidden", "after_due_date", "after_published", "visible"}
FORMATS = {"text", "html", "simple_format", "md", "ansi"}
GS_TOP = {"score", "execution_time", "output", "output_format", "test_output_format", "test_name_format",
          "visibility", "stdout_visibility", "extra_data", "tests", "leaderboard"}
GS_TEST = {"score", "max_score", "status", "name", "name_format", "number", "output", "output_format", "tags",
           "visibility", "extra_data"}
PL_TOP = {"gradable", "score", "message", "output", "format_errors", "images", "tests"}
PL_TEST = {"name", "description", "points", "max_points", "message", "output", "images"}


def number(x):
    return isinstance(x, (int, float)) and not isinstance(x, bool)


def gradescope(doc):
    errors = []
    if not isinstance(doc, dict):
        return ["the document is not an object"]
    for k in doc:
        if k not in GS_TOP:
            errors.append("unknown top-level key %r" % k)
    tests = doc.get("tests")
    if "score" not in doc and not (isinstance(tests, list) and tests and all("score" in t for t in tests if isinstance(t, dict))):
        errors.append("no top-level score and not every test has one")
    if "score" in doc and not number(doc["score"]):
        errors.append("score is not a number: %r" % (doc["score"],))
    if "execution_time" in doc and not number(doc["execution_time"]):
        errors.append("execution_time is not a number")
    for k in ("visibility", "stdout_visibility"):
        if k in doc and doc[k] not in VISIBILITY:
            errors.append("%s %r is not one of %s" % (k, doc[k], sorted(VISIBILITY)))
    for k in ("output_format", "test_output_format", "test_name_format"):
        if k in doc and doc[k] not in FORMATS:
            errors.append("%s %r is not one of %s" % (k, doc[k], sorted(FORMATS)))
    if "output" in doc and not isinstance(doc["output"], str):
        errors.append("output is not a string")
    if isinstance(doc.get("output"), str) and "\r" in doc["output"]:
        errors.append("output has a CR: Gradescope asks for Unix line ends")
    if tests is not None and not isinstance(tests, list):
        errors.append("tests is not a list")
        tests = []
    total = 0.0
    scored = 0
    for i, t in enumerate(tests or []):
        where = "tests[%d]" % i
        if not isinstance(t, dict):
            errors.append(where + " is not an object")
            continue
        for k in t:
            if k not in GS_TEST:
                errors.append("%s: unknown key %r" % (where, k))
        for k in ("score", "max_score"):
            if k in t and not number(t[k]):
                errors.append("%s: %s is not a number" % (where, k))
        if number(t.get("score")) and number(t.get("max_score")):
            if t["score"] > t["max_score"] + 1e-9 or t["score"] < 0:
                errors.append("%s: score %r outside [0, max_score %r]" % (where, t["score"], t["max_score"]))
        if "status" in t and t["status"] not in ("passed", "failed"):
            errors.append("%s: status %r is not passed or failed" % (where, t["status"]))
        if "visibility" in t and t["visibility"] not in VISIBILITY:
            errors.append("%s: visibility %r" % (where, t["visibility"]))
        for k in ("output_format", "name_format"):
            if k in t and t[k] not in FORMATS:
                errors.append("%s: %s %r" % (where, k, t[k]))
        for k in ("name", "output", "number"):
            if k in t and not isinstance(t[k], str):
                errors.append("%s: %s is not a string" % (where, k))
        if isinstance(t.get("output"), str) and "\r" in t["output"]:
            errors.append("%s: output has a CR" % where)
        if "tags" in t and not (isinstance(t["tags"], list) and all(isinstance(x, str) for x in t["tags"])):
            errors.append("%s: tags is not a list of strings" % where)
        if number(t.get("score")):
            total += t["score"]
            scored += 1
    if number(doc.get("score")) and scored and abs(total - doc["score"]) > 0.01 * max(1, scored):
        errors.append("the tests' scores add up to %r, the score is %r" % (total, doc["score"]))
    return errors


def prairielearn(doc, size):
    errors = []
    if size > 1 << 20:
        errors.append("the file is %d bytes, over PrairieLearn's 1 MB" % size)
    if not isinstance(doc, dict):
        return errors + ["the document is not an object"]
    for k in doc:
        if k not in PL_TOP:
            errors.append("unknown top-level key %r" % k)
    gradable = doc.get("gradable", True)
    if not isinstance(gradable, bool):
        errors.append("gradable is not a boolean")
    if gradable:
        if "score" not in doc:
            errors.append("a gradable result has no score")
        elif not number(doc["score"]) or not 0 <= doc["score"] <= 1:
            errors.append("score %r is not a number in [0, 1]" % (doc["score"],))
    else:
        fe = doc.get("format_errors")
        if fe is not None and not (isinstance(fe, str) or (isinstance(fe, list) and all(isinstance(x, str) for x in fe))):
            errors.append("format_errors is neither a string nor a list of strings")
    for k in ("message", "output"):
        if k in doc and not isinstance(doc[k], str):
            errors.append("%s is not a string" % k)
    tests = doc.get("tests", [])
    if not isinstance(tests, list):
        return errors + ["tests is not a list"]
    total = 0.0
    maximum = 0.0
    for i, t in enumerate(tests):
        where = "tests[%d]" % i
        if not isinstance(t, dict):
            errors.append(where + " is not an object")
            continue
        for k in t:
            if k not in PL_TEST:
                errors.append("%s: unknown key %r" % (where, k))
        for k in ("name", "description", "message", "output"):
            if k in t and not isinstance(t[k], str):
                errors.append("%s: %s is not a string" % (where, k))
        for k in ("points", "max_points"):
            if k in t and not number(t[k]):
                errors.append("%s: %s is not a number" % (where, k))
        if number(t.get("points")) and number(t.get("max_points")):
            if t["points"] > t["max_points"] + 1e-9 or t["points"] < 0:
                errors.append("%s: points %r outside [0, max_points %r]" % (where, t["points"], t["max_points"]))
            total += t["points"]
            maximum += t["max_points"]
    if gradable and number(doc.get("score")) and maximum > 0 and abs(total / maximum - doc["score"]) > 0.001 * max(1, len(tests)):
        errors.append("the tests' points make %r of their maximum, the score is %r" % (total / maximum, doc["score"]))
    return errors


def validate(platform, text):
    doc = json.loads(text)
    return gradescope(doc) if platform == "gradescope" else prairielearn(doc, len(text.encode()))


def self_test():
    """Every rule must refuse a document that breaks it, and accept the documented examples."""
    good_gs = {"score": 3.0, "output": "ok", "stdout_visibility": "hidden", "tests": [
        {"name": "a", "score": 1.0, "max_score": 1.0, "status": "passed", "output": "x", "visibility": "visible"},
        {"name": "b", "score": 2.0, "max_score": 3.0, "status": "failed", "output_format": "md"},
        {"name": "info", "status": "passed"}]}
    good_pl = {"gradable": True, "score": 0.25, "message": "m", "output": "o", "tests": [
        {"name": "T1", "description": "d", "points": 1, "max_points": 1, "message": "ok", "output": "x"},
        {"name": "T2", "description": "d", "points": 0, "max_points": 3, "message": "no", "output": "y"}]}
    bad = [
        ("gradescope", dict(good_gs, visibility="sometimes")),
        ("gradescope", dict(good_gs, score="3")),
        ("gradescope", dict(good_gs, grade=3)),
        ("gradescope", dict(good_gs, output="a\r\nb")),
        ("gradescope", dict(good_gs, score=5.0)),
        ("gradescope", dict(good_gs, tests=[dict(good_gs["tests"][0], status="ok")])),
        ("gradescope", dict(good_gs, tests=[dict(good_gs["tests"][0], score=2.0)])),
        ("gradescope", dict(good_gs, tests=[dict(good_gs["tests"][0], points=1)])),
        ("gradescope", dict(good_gs, tests=[dict(good_gs["tests"][1], output_format="markdown")])),
        ("gradescope", {"tests": [{"name": "no score"}]}),
        ("prairielearn", dict(good_pl, score=25)),
        ("prairielearn", dict(good_pl, gradable="yes")),
        ("prairielearn", {"gradable": True, "message": "no score"}),
        ("prairielearn", dict(good_pl, tests=[dict(good_pl["tests"][0], points=2)])),
        ("prairielearn", dict(good_pl, tests=[dict(good_pl["tests"][0], score=1)])),
        ("prairielearn", dict(good_pl, score=0.9)),
        ("prairielearn", dict(good_pl, gradable=False, format_errors=[1, 2])),
        ("prairielearn", dict(good_pl, output="x" * (1 << 20))),
    ]
    failures = []
    for platform, doc in (("gradescope", good_gs), ("prairielearn", good_pl)):
        e = validate(platform, json.dumps(doc))
        if e:
            failures.append("a valid %s document was refused: %s" % (platform, e))
    for platform, doc in bad:
        if not validate(platform, json.dumps(doc)):
            failures.append("a broken %s document was accepted: %s" % (platform, json.dumps(doc)[:200]))
    for f in failures:
        print("SELF-TEST FAILURE: " + f)
    print("self-test: %d broken documents refused, 2 valid ones accepted" % (len(bad) - len(failures)) if not failures
          else "self-test FAILED")
    return 1 if failures else 0


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    if len(sys.argv) != 3 or sys.argv[1] not in ("gradescope", "prairielearn"):
        print(__doc__)
        return 2
    with open(sys.argv[2], encoding="utf-8") as f:
        text = f.read()
    errors = validate(sys.argv[1], text)
    for e in errors:
        print("INVALID: " + e)
    if not errors:
        print("valid %s results: %s" % (sys.argv[1], sys.argv[2]))
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
