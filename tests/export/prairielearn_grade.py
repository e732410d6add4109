#!/usr/bin/env python3
"""Runs an exported PrairieLearn question's server.py as PrairieLearn would, on every variant.

    prairielearn_grade.py QUESTION_DIR

For each variant in variants.json: generate() with PrairieLearn's data dict; then grade() of
the key's own answers (score 1), of each listed mistake (score 0 with wobble's message), of a
principal axis with its sign flipped and of the axes as rows (score 1), of moments in another
order (score 1), of each answer 3 tolerances off (score 0), and of a vector with its last
entry 3 tolerances off (score 0, the entry named as wobble check names it), and of Euler angles
with the last a whole turn on (score 1, named). Exits 1 naming the first
difference; prints what it graded.
"""
import copy
import importlib.util
import json
import math
import os
import sys


def load_server(folder):
    spec = importlib.util.spec_from_file_location("server", os.path.join(folder, "server.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def fresh_data(folder, seed):
    # The fields PrairieLearn's data dict has for generate() and grade() (its question docs).
    return {"params": {}, "correct_answers": {}, "submitted_answers": {}, "format_errors": {},
            "partial_scores": {}, "score": 0, "feedback": {}, "variant_seed": seed,
            "options": {"question_path": folder}, "raw_submitted_answers": {},
            "editable": True, "panel": "question", "extensions": {}}


def submitted(answer, flat):
    """As PrairieLearn's elements store a parsed submission."""
    if answer["shape"] == "scalar":
        return flat[0]
    rows, cols = answer["rows"], answer["cols"]
    # pl-matrix-component-input stores pl.to_json(numpy array): {"_type": "ndarray", "_value": ...}
    return {"_type": "ndarray", "_value": [[flat[r * cols + c] for c in range(cols)]
                                            for r in range(rows)], "_dtype": "float64"}


def main():
    folder = os.path.abspath(sys.argv[1])
    server = load_server(folder)
    with open(os.path.join(folder, "variants.json"), encoding="utf-8") as f:
        table = json.load(f)
    numbers = [v["number"] for v in table["variants"]]
    counts = {"right": 0, "mistakes": 0, "flipped axes": 0, "rows": 0, "reordered": 0, "off": 0}
    failures = []
    for seed in range(len(numbers) * 3):
        data = fresh_data(folder, seed)
        server.generate(data)
        if data["params"]["variant"] not in numbers:
            failures.append("generate() picked variant %s, not exported" % data["params"]["variant"])
    for variant in table["variants"]:
        base = fresh_data(folder, 0)
        base["params"]["variant"] = variant["number"]
        answers = variant["answers"]

        def grade(name, flat):
            data = copy.deepcopy(base)
            for a in answers:
                data["submitted_answers"][a["input"]] = submitted(a, a["value"])
            target = next(a for a in answers if a["input"] == name)
            data["submitted_answers"][name] = submitted(target, flat)
            server.grade(data)
            return data["partial_scores"][name]["score"], data["feedback"][name], data["score"]

        def expect(what, name, flat, score, message=None):
            got, feedback, _ = grade(name, flat)
            if got != score or (message is not None and feedback != message):
                failures.append("variant %d %s (%s): score %s %r, expected %s %r" % (
                    variant["number"], name, what, got, feedback, score, message))

        data = copy.deepcopy(base)
        for a in answers:
            data["submitted_answers"][a["input"]] = submitted(a, a["value"])
        server.grade(data)
        if data["score"] != 1:
            failures.append("variant %d: the key scores %s" % (variant["number"], data["score"]))
        counts["right"] += len(answers)
        for a in answers:
            for m in a["mistakes"]:
                expect("mistake", a["input"], m["values"], 0, "incorrect: " + m["message"])
                counts["mistakes"] += 1
            value = a["value"]
            tol = a["rel_tol"]
            off = [x * (1 + 3 * tol) if x != 0 else 3 * tol * a["zero_scale"] for x in value]
            if a["kind"] != "principal_axes" and not any(
                    all(abs(o - w) <= tol * abs(w) for o, w in zip(off, m["values"]))
                    for m in a["mistakes"]):
                expect("3 tolerances off", a["input"], off, 0)
                counts["off"] += 1
            if a["kind"] == "vector" and value[-1] != 0:
                # One entry off: the feedback names it as wobble check does ("entry e₃", "c₃").
                one_off = value[:-1] + [value[-1] * (1 + 3 * tol)]
                if not any(all(abs(o - w) <= tol * abs(w) for o, w in zip(one_off, m["values"]))
                           for m in a["mistakes"]):
                    expect("last entry off", a["input"], one_off, 0,
                           "incorrect: %s is off by %.3g%%" % (a["entries"][-1], 300 * tol))
                    counts["entry named"] = counts.get("entry named", 0) + 1
            if a.get("whole_turns"):
                # Euler angles: the last one a whole turn on is the same angle, named.
                turned = value[:-1] + [value[-1] + 2 * math.pi]
                expect("last angle a turn on", a["input"], turned, 1,
                       "correct (%s differs from the key's by whole turns: the same angle)"
                       % a["entries"][-1])
                counts["whole turns"] = counts.get("whole turns", 0) + 1
            if a["kind"] == "principal_axes":
                flipped = list(value)
                for r in range(3):
                    flipped[3 * r + 1] = -flipped[3 * r + 1]
                expect("axis e2 flipped", a["input"], flipped, 1)
                counts["flipped axes"] += 1
                for columns in a["eigenspaces"]:
                    if len(columns) != 2:
                        continue
                    # A degenerate pair: any perpendicular pair of its plane, here turned 30°.
                    i, j = columns
                    c, s = 0.8660254037844386, 0.5
                    turned = list(value)
                    for r in range(3):
                        turned[3 * r + i] = c * value[3 * r + i] + s * value[3 * r + j]
                        turned[3 * r + j] = -s * value[3 * r + i] + c * value[3 * r + j]
                    expect("degenerate pair turned 30 degrees", a["input"], turned, 1)
                    counts["turned in plane"] = counts.get("turned in plane", 0) + 1
                rows = [value[3 * c + r] for r in range(3) for c in range(3)]
                expect("axes as rows", a["input"], rows, 1)
                counts["rows"] += 1
            if a["kind"] == "principal_moments":
                expect("moments reversed", a["input"], list(reversed(value)), 1)
                counts["reordered"] += 1
    print("%s: %d variants; graded %s" % (os.path.basename(folder), len(numbers),
                                          ", ".join("%d %s" % (n, k) for k, n in counts.items())))
    if failures:
        print("\n".join(failures[:20]))
        sys.exit(1)


if __name__ == "__main__":
    main()
