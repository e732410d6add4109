#!/usr/bin/env python3
"""Exports a Gradescope autograder and runs it as Gradescope would, in a temporary root.

    gradescope_test.py WOBBLE PROBLEM_ID

The zip is unpacked into ROOT/source (scripts must be executable); run_autograder runs with
AUTOGRADER_ROOT=ROOT and WOBBLE=the built program on: the key's answers of variant 3, "none"
for those that do not exist there (full score, one test each), the same with one answer doubled, one left out and a line naming no answer (the
doubled one fails with wobble's "2 times" message, the missing one "not answered", the stray
line reported), and no answers file at all (score 0 with a message). The package carried is a
stand-in with the Debian magic (the real one is installed by the package test).
"""
import json
import os
import shutil
import stat
import subprocess
import sys
import tempfile
import zipfile

failures = []


def expect(condition, message):
    if not condition:
        failures.append(message)


def answer_line(a):
    value = a["value"]
    unit = " " + a["unit"] if a["unit"] else ""
    return "%s = %s%s" % (a["name"], json.dumps(value), unit)


def grade(root, wobble, lines):
    sub = os.path.join(root, "submission")
    shutil.rmtree(sub, ignore_errors=True)
    os.makedirs(sub)
    if lines is not None:
        with open(os.path.join(sub, "answers.txt"), "w", encoding="utf-8") as f:
            f.write("\n".join(lines) + "\n")
    env = dict(os.environ, AUTOGRADER_ROOT=root, WOBBLE=wobble)
    run = subprocess.run([os.path.join(root, "source", "run_autograder")], env=env,
                         capture_output=True, text=True)
    expect(run.returncode == 0, "run_autograder exit %d: %s" % (run.returncode, run.stderr))
    with open(os.path.join(root, "results", "results.json"), encoding="utf-8") as f:
        return json.load(f)


def main():
    wobble, problem = os.path.abspath(sys.argv[1]), sys.argv[2]
    with tempfile.TemporaryDirectory() as tmp:
        deb = os.path.join(tmp, "wobble_0_amd64.deb")
        with open(deb, "wb") as f:
            f.write(b"!<arch>\ndebian-binary   0           0     0     100644  4         `\n2.0\n")
        zip_path = os.path.join(tmp, "autograder.zip")
        subprocess.run([wobble, "export", "gradescope", problem, "--deb", deb, "--out", zip_path],
                       check=True, capture_output=True)
        root = os.path.join(tmp, "autograder")
        source = os.path.join(root, "source")
        with zipfile.ZipFile(zip_path) as z:
            names = sorted(z.namelist())
            expect(names == sorted(["setup.sh", "run_autograder", problem + ".toml",
                                    "wobble_0_amd64.deb"]), "zip holds %s" % names)
            for info in z.infolist():
                z.extract(info, source)
                mode = (info.external_attr >> 16) & 0o777
                os.chmod(os.path.join(source, info.filename), mode)
                if info.filename in ("setup.sh", "run_autograder"):
                    expect(mode & stat.S_IXUSR, "%s is not executable" % info.filename)
        key = json.loads(subprocess.run([wobble, "solve", problem, "--variant", "3", "--format",
                                         "json"], check=True, capture_output=True,
                                        text=True).stdout)
        answers = [a for p in key["parts"] for a in p["answers"]]
        # An answer that does not exist at the variant's values (a heavy top too slow for steady
        # precession) is asked too, and "none", as the key prints it, is right for it.
        absent = [name for p in key["parts"] for name in p.get("absent", [])]
        right = (["variant = 3"] + [answer_line(a) for a in answers] +
                 ["%s = none at these values" % name for name in absent])
        results = grade(root, wobble, right)
        expect(results["score"] == len(answers) + len(absent), "the key scores %s of %d: %s" % (
            results["score"], len(answers) + len(absent), json.dumps(results)[:400]))
        expect(len(results["tests"]) == len(answers) + len(absent),
               "%d tests for %d answers" % (len(results["tests"]), len(answers) + len(absent)))
        expect(all(t["max_score"] == 1 and t["status"] == "passed" for t in results["tests"]),
               "a test of the key failed")
        doubled = dict(answers[0])
        doubled["value"] = json.loads(json.dumps(doubled["value"]), parse_float=lambda x: 2 * float(x))
        wrong = (["variant = 3", answer_line(doubled)] + [answer_line(a) for a in answers[2:]] +
                 ["%s = none" % name for name in absent])
        wrong.append("no_such_answer = 1")
        results = grade(root, wobble, wrong)
        tests = results["tests"]
        expect(results["score"] == len(answers) + len(absent) - 2,
               "wrong submission scores %s" % results["score"])
        expect("2 times the answer" in tests[0]["output"], "doubled: %s" % tests[0]["output"])
        expect("not answered" in tests[1]["output"], "missing: %s" % tests[1]["output"])
        expect("no_such_answer" in results.get("output", ""), "stray line not reported")
        results = grade(root, wobble, None)
        expect(results["score"] == 0 and "No answers file" in results["output"], "no file: %s" % results)
        total = len(answers) + len(absent)
        print("%s: autograder of %d files; key %d/%d (%d of them none at these values), wrong "
              "submission %d/%d" % (problem, len(names), total, total, len(absent), total - 2,
                                    total))
    if failures:
        print("\n".join(failures))
        sys.exit(1)


if __name__ == "__main__":
    main()
