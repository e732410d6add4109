#!/usr/bin/env python3
"""Exports one problem to PrairieLearn and Moodle as an instructor would, and checks the files.

    export_test.py WOBBLE PROBLEM_ID

- PrairieLearn: info.json has every field PrairieLearn requires (uuid, type, title, topic) and
  no other than its schema allows; server.py grades every variant as prairielearn_grade.py says.
- Moodle: the XML is well formed and has, for each calculated question, each element Moodle's
  XML import reads (question/format/xml/format.php, import_calculated); every dataset's item
  count matches its items; every answer's formula names a dataset.
- Round trip: for every exported variant, the values in both exports equal
  `wobble solve ID --variant N --format json`, bit for bit. Each Moodle mistake's feedback, its
  wildcards put in as Moodle puts them in, is in every variant that has the mistake what
  `wobble check` says of that value (checked in the first and the last such variant; every
  variant's wildcards have a value).
"""
import json
import os
import re
import subprocess
import sys
import tempfile
import tomllib
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import prairielearn_grade  # noqa: E402

VARIANTS = "1-20"
PL_ALLOWED = {"comment", "uuid", "type", "title", "topic", "tags", "clientFiles",
              "clientTemplates", "template", "gradingMethod", "singleVariant",
              "showCorrectAnswer", "partialCredit", "options", "externalGradingOptions",
              "dependencies", "workspaceOptions", "sharingSets", "sharePublicly",
              "shareSourcePublicly"}
UUID = re.compile(r"^[0-9a-fA-F]{8}-[0-9a-fA-F]{4}-[0-9a-fA-F]{4}-[0-9a-fA-F]{4}-[0-9a-fA-F]{12}$")
failures = []


def fail(message):
    failures.append(message)


def run(args):
    out = subprocess.run(args, capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit("%s failed (%d): %s" % (" ".join(args), out.returncode, out.stderr))
    return out.stdout


def flat(value):
    if isinstance(value, list):
        return [x for row in value for x in flat(row)]
    return [value]


KEYS = {}
ENTRIES = {}  # answer name -> the key's names of its entries
ANGLES = set()  # names of the answers that are Euler angles (a vector in rad): up to whole turns
UNITS = {}  # answer name -> the key's unit
FEEDBACK_JUDGED = [0]  # mistakes' feedbacks compared with wobble check's


def key_values(wobble, problem, number):
    """name -> flat values of `wobble solve --variant number --format json`."""
    if number not in KEYS:
        key = json.loads(run([wobble, "solve", problem, "--variant", str(number), "--format", "json"]))
        KEYS[number] = {a["name"]: flat(a["value"]) for p in key["parts"] for a in p["answers"]}
        ENTRIES.update({a["name"]: a.get("entries", []) for p in key["parts"] for a in p["answers"]})
        ANGLES.update(a["name"] for p in key["parts"] for a in p["answers"]
                      if a["kind"] == "vector" and a.get("unit") == "rad")
        UNITS.update({a["name"]: a.get("unit", "") for p in key["parts"] for a in p["answers"]})
    return KEYS[number]


def check_prairielearn(wobble, problem, folder):
    question = os.path.join(folder, problem)
    with open(os.path.join(question, "info.json"), encoding="utf-8") as f:
        info = json.load(f)
    for field in ("uuid", "type", "title", "topic"):
        if field not in info:
            fail("info.json: no %s" % field)
    if set(info) - PL_ALLOWED:
        fail("info.json: fields PrairieLearn refuses: %s" % sorted(set(info) - PL_ALLOWED))
    if not UUID.match(info.get("uuid", "")) or info.get("type") != "v3":
        fail("info.json: uuid %r, type %r" % (info.get("uuid"), info.get("type")))
    with open(os.path.join(question, "variants.json"), encoding="utf-8") as f:
        table = json.load(f)
    for v in table["variants"]:
        key = key_values(wobble, problem, v["number"])
        for a in v["answers"]:
            if a["value"] != key.get(a["name"]):
                fail("PrairieLearn variant %d %s: %s, solve gives %s" % (
                    v["number"], a["name"], a["value"], key.get(a["name"])))
    with open(os.path.join(question, "question.html"), encoding="utf-8") as f:
        check_prairielearn_hints(problem, f.read())
    sys.argv = ["prairielearn_grade.py", question]
    try:
        prairielearn_grade.main()
    except SystemExit as e:
        if e.code:
            fail("PrairieLearn grading failed")
    return len(table["variants"])


def problem_hints(problem):
    """part id -> hint of the problem file (problems/ID.toml beside the tests)."""
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "problems",
                        problem + ".toml")
    with open(path, "rb") as f:
        return {p["id"]: p.get("hint", "") for p in tomllib.load(f)["parts"]}


def math_count(text):
    return len(re.findall(r"\$[^$]+\$", text))


def check_prairielearn_hints(problem, html):
    """Each part's hint once, after the part's inputs and before the next part, its math for
    MathJax as $...$ as the question's; none for a part without one."""
    hints = problem_hints(problem)
    parts = re.split(r"<p><strong>\((\w+)\)</strong>", html)[1:]
    for part_id, body in zip(parts[0::2], parts[1::2]):
        shown = re.findall(r'<pl-hidden-hints>\n<pl-hint show-after-submission="2" '
                           r'hint-name="Hint for \((\w+)\)">(.*?)</pl-hint>\n</pl-hidden-hints>',
                           body, re.S)
        want = hints.get(part_id, "")
        if not want:
            if shown or "pl-hint" in body:
                fail("PrairieLearn (%s): a hint, but the problem file has none" % part_id)
            continue
        if len(shown) != 1 or shown[0][0] != part_id:
            fail("PrairieLearn (%s): hints %r" % (part_id, shown))
            continue
        if math_count(shown[0][1]) != math_count(want) or "\\(" in shown[0][1]:
            fail("PrairieLearn (%s): hint %r, from %r" % (part_id, shown[0][1], want))
    if sum(1 for h in hints.values() if h) != html.count("<pl-hint "):
        fail("PrairieLearn: %d hints for %d parts with one" % (
            html.count("<pl-hint "), sum(1 for h in hints.values() if h)))


def text(element, path):
    found = element.find(path)
    if found is None:
        fail("moodle: <%s> missing in %s" % (path, element.tag))
        return ""
    return found.text or ""


def check_moodle_hint(name, question, hints):
    """The part's hint, once, as HTML with its math in \\( \\) as the question text's; none for
    a part without one."""
    want = hints.get(re.match(r"^\S+ \((\w+)\)", name).group(1), "")
    found = question.findall("hint")
    if not want:
        if found:
            fail("moodle: %s: a hint, but the problem file has none" % name)
        return
    if len(found) != 1 or found[0].get("format") != "html":
        fail("moodle: %s: %d hints" % (name, len(found)))
        return
    shown = text(found[0], "text")
    if "$" in shown or shown.count("\\(") != math_count(want) or not shown.strip():
        fail("moodle: %s: hint %r, from %r" % (name, shown, want))


def check_moodle(wobble, problem, quiz_file):
    root = ET.parse(quiz_file).getroot()
    if root.tag != "quiz":
        fail("moodle: root is <%s>, not <quiz>" % root.tag)
    questions = root.findall("question")
    if not questions or questions[0].get("type") != "category":
        fail("moodle: the first question is not the category")
    checked = 0
    hints = problem_hints(problem)
    for q in questions[1:]:
        if q.get("type") != "calculated":
            fail("moodle: question type %s" % q.get("type"))
            continue
        name = text(q, "name/text")
        if q.find("questiontext").get("format") != "html":
            fail("moodle: %s: question text format" % name)
        text(q, "questiontext/text")
        check_moodle_hint(name, q, hints)
        for tag in ("generalfeedback/text", "defaultgrade", "penalty", "hidden", "synchronize",
                    "single", "answernumbering", "shuffleanswers", "unitgradingtype",
                    "unitpenalty", "showunits", "unitsleft"):
            text(q, tag)
        datasets = {}
        raw = {}  # the items as written, as Moodle shows them in a feedback
        for d in q.findall("dataset_definitions/dataset_definition"):
            for tag in ("status/text", "name/text", "type", "distribution/text", "minimum/text",
                        "maximum/text", "decimals/text", "itemcount", "number_of_items"):
                text(d, tag)
            items = d.findall("dataset_items/dataset_item")
            numbers = [int(text(i, "number")) for i in items]
            if numbers != list(range(1, len(items) + 1)) or int(text(d, "itemcount")) != len(items):
                fail("moodle: %s: dataset %s items %s" % (name, text(d, "name/text"), numbers))
            datasets[text(d, "name/text")] = [float(text(i, "value")) for i in items]
            raw[text(d, "name/text")] = [text(i, "value") for i in items]
        # Moodle substitutes every {name} it has a dataset for: the text's only braces are
        # wobble's wildcards, the problem's own (LaTeX's) are entities.
        for word in re.findall(r"\{([^{}]*)\}", text(q, "questiontext/text") + "".join(
                text(h, "text") for h in q.findall("hint"))):
            if word not in datasets:
                fail("moodle: %s: {%s} in the text is no wildcard" % (name, word))
        answers = q.findall("answer")
        mistakes = []
        turns = 0
        if not answers or answers[0].get("fraction") != "100":
            fail("moodle: %s: the right answer is not first" % name)
        for a in answers:
            for tag in ("text", "tolerance", "tolerancetype", "correctanswerformat",
                        "correctanswerlength", "feedback/text"):
                text(a, tag)
            formula = text(a, "text")
            # An Euler angle a turn either way: right, said so.
            if formula in ("{ans} + 2*pi()", "{ans} - 2*pi()"):
                if a.get("fraction") != "100" or "whole turn" not in text(a, "feedback/text"):
                    fail("moodle: %s: %s is not right as a whole turn" % (name, formula))
                turns += 1
                continue
            wildcard = formula.strip("{}")
            if wildcard not in datasets:
                fail("moodle: %s: answer {%s} has no dataset" % (name, wildcard))
            elif a.get("fraction") == "0":
                mistakes.append(a)
        # Round trip: "NAME" or "NAME, entry ..." against solve's values of that variant.
        parts = re.match(r"^\S+ \((\w+)\) (\w+)(.*)$", name)
        answer = parts.group(2)
        key_values(wobble, problem, int(datasets["variant"][0]))  # the entries' names
        entry = entry_index(parts.group(3), ENTRIES.get(answer, []))
        if (answer in ANGLES) != (turns == 2):
            fail("moodle: %s: %d answers a whole turn on, for %s" % (
                name, turns, "an Euler angle" if answer in ANGLES else "no angle"))
        for a in mistakes:
            check_mistake_feedback(wobble, problem, name, answer, not parts.group(3), a, raw,
                                   datasets)
        for number, value in zip(datasets["variant"], datasets["ans"]):
            want = key_values(wobble, problem, int(number))[answer][entry]
            if value != want:
                fail("moodle: %s variant %d: %r, solve gives %r" % (name, number, value, want))
            checked += 1
    return len(questions) - 1, checked


def judged(wobble, problem, number, answer, typed):
    """What `wobble check` says of `typed` for `answer` in variant `number`: its feedback."""
    with tempfile.NamedTemporaryFile("w", suffix=".txt", delete=False) as f:
        f.write("variant = %d\n%s = %s\n" % (number, answer, typed))
    try:
        out = subprocess.run([wobble, "check", problem, "--answers", f.name, "--format", "json"],
                             capture_output=True, text=True)
    finally:
        os.unlink(f.name)
    for a in json.loads(out.stdout)["answers"]:
        if a["name"] == answer:
            return a["verdict"], a["feedback"]
    return None, []


def check_mistake_feedback(wobble, problem, name, answer, whole, a, raw, datasets):
    """A mistake's feedback with Moodle's wildcards put in, in each variant that has the mistake
    (its value is not the right one there); for a one-number answer, in the first and the last
    such variant, the line `wobble check` says of that value."""
    feedback = text(a, "feedback/text")
    values = raw[text(a, "text").strip("{}")]
    having = [i for i in range(len(values)) if float(values[i]) != datasets["ans"][i]]
    for i in having:
        number = datasets["variant"][i]
        said = re.sub(r"\{(\w+)\}", lambda m: raw.get(m.group(1), [m.group(0)] * (i + 1))[i],
                      feedback)
        if "{" in said:
            fail("moodle: %s variant %d: feedback %r has a wildcard without a dataset" % (
                name, number, said))
        # The first and the last that have it: a feedback of one variant's numbers fails one.
        if not whole or i not in (having[0], having[-1]):
            continue
        FEEDBACK_JUDGED[0] += 1
        typed = values[i] + (" " + UNITS[answer] if UNITS.get(answer) else "")
        verdict, lines = judged(wobble, problem, int(number), answer, typed)
        if verdict != "incorrect: " + answer or not lines or "incorrect: " + lines[0] != said:
            fail("moodle: %s variant %d: %r says %r; wobble check says %r %r" % (
                name, number, typed, said, verdict, lines[:1]))


def entry_index(words, names):
    """The entry a question's name asks for: ", c₁" by the key's names for its entries, ", its
    e₁ component" by axis, ", the smallest moment" by rank, ", entry (1, 2)" by position."""
    if not words:
        return 0
    if words[2:] in names:
        return names.index(words[2:])
    for i, rank in enumerate(("smallest", "middle", "largest")):
        if rank in words:
            return i
    m = re.search(r"its (\S+) component", words)
    if m:
        for axes in (("x", "y", "z"), ("e₁", "e₂", "e₃"), ("e₁′", "e₂′", "e₃′")):
            if m.group(1) in axes:
                return axes.index(m.group(1))
        fail("moodle: no axis %r" % m.group(1))
        return 0
    m = re.search(r"entry \((\d+), (\d+)\)", words)
    if m:
        return (int(m.group(1)) - 1) * 3 + int(m.group(2)) - 1
    return int(re.search(r"entry (\d+)", words).group(1)) - 1


def main():
    wobble, problem = sys.argv[1], sys.argv[2]
    with tempfile.TemporaryDirectory() as tmp:
        run([wobble, "export", "prairielearn", problem, "--variants", VARIANTS, "--out",
             os.path.join(tmp, "questions")])
        variants = check_prairielearn(wobble, problem, os.path.join(tmp, "questions"))
        quiz = os.path.join(tmp, "quiz.xml")
        run([wobble, "export", "moodle", problem, "--variants", VARIANTS, "--out", quiz])
        questions, items = check_moodle(wobble, problem, quiz)
    print("%s: PrairieLearn %d variants, Moodle %d questions (%d dataset items against solve, "
          "%d mistakes' feedback against check)" % (
              problem, variants, questions, items, FEEDBACK_JUDGED[0]))
    if failures:
        print("\n".join(failures[:30]))
        sys.exit(1)


if __name__ == "__main__":
    main()
