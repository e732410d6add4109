# PrairieLearn question code written by `wobble export prairielearn`.
#
# generate() picks one of wobble's variants from variants.json (beside this file); grade()
# applies wobble's rules to what the student typed: a relative tolerance (or significant
# figures), a zero judged against the largest value of the same unit, principal moments in any
# order, principal axes each up to sign and length, as rows or columns, a degenerate pair's axes
# anywhere in its plane, Euler angles up to whole turns; and a wrong answer that a known mistake
# leads to gets wobble's message for it. The values and messages were computed by wobble for each
# variant; nothing here solves the problem. Plain Python 3, no packages.
import json
import math
import os
import random

_VARIANTS = None


def _folder(data):
    options = data.get("options") or {}
    return options.get("question_path") or os.path.dirname(os.path.abspath(__file__))


def _variants(data):
    global _VARIANTS
    if _VARIANTS is None:
        with open(os.path.join(_folder(data), "variants.json"), encoding="utf-8") as f:
            _VARIANTS = json.load(f)
    return _VARIANTS


def _matrix(answer, values):
    rows, cols = answer["rows"], answer["cols"]
    return [[values[r * cols + c] for c in range(cols)] for r in range(rows)]


def generate(data):
    table = _variants(data)
    seed = data.get("variant_seed")
    chooser = random.Random(seed) if seed is not None else random.Random()
    variant = chooser.choice(table["variants"])
    data["params"]["variant"] = variant["number"]
    data["params"]["values"] = variant["values"]
    for answer in variant["answers"]:
        if answer["shape"] == "scalar":
            data["correct_answers"][answer["input"]] = answer["value"][0]
        else:
            data["correct_answers"][answer["input"]] = _matrix(answer, answer["value"])


def _close(typed, expected, rules, answer):
    scale = abs(expected) if expected != 0 else answer["zero_scale"]
    sigfigs = rules.get("sigfigs")
    if sigfigs:
        place = 10.0 ** (math.floor(math.log10(scale)) - sigfigs + 1)
        return abs(typed - expected) <= 0.5 * place * (1 + rules["half_unit_slack"])
    return abs(typed - expected) <= answer["rel_tol"] * scale


def _all_close(typed, expected, rules, answer):
    return len(typed) == len(expected) and all(
        _close(t, e, rules, answer) for t, e in zip(typed, expected))


def _entry_name(answer, i):
    # As wobble check names it: "entry e₁", "c₁", "the smallest moment", "entry (1, 2)".
    return answer["entries"][i]


def _how_far(answer, typed, rules):
    expected = answer["value"]
    if len(typed) == 1:
        k = expected[0]
        return ["off by %.3g%% of the answer" % (100 * abs(typed[0] - k) / max(abs(k), 1e-300))]
    out = []
    for i, (t, k) in enumerate(zip(typed, expected)):
        if _close(t, k, rules, answer):
            continue
        scale = abs(k) if k != 0 else answer["zero_scale"]
        out.append("%s is off by %.3g%%" % (_entry_name(answer, i), 100 * abs(t - k) / scale))
    return out


def _unit(v):
    n = math.sqrt(sum(x * x for x in v))
    return [x / n for x in v] if n > 0 and math.isfinite(n) else None


def _distance(axes, columns, v):
    # Sine of the angle between unit v and the span of the key's columns.
    projection = [0.0, 0.0, 0.0]
    for c in columns:
        d = sum(axes[r][c] * v[r] for r in range(3))
        for r in range(3):
            projection[r] += d * axes[r][c]
    return math.sqrt(sum((v[r] - projection[r]) ** 2 for r in range(3)))


def _axes_right(vectors, answer, tol):
    axes = _matrix(answer, answer["value"])
    spaces = answer["eigenspaces"]
    units, space_of = [], []
    for v in vectors:
        u = _unit(v)
        if u is None:
            return False
        distances = [_distance(axes, s, u) for s in spaces]
        best = min(range(len(spaces)), key=lambda s: distances[s])
        if distances[best] > tol:
            return False
        units.append(u)
        space_of.append(best)
    for s, columns in enumerate(spaces):
        members = [i for i in range(3) if space_of[i] == s]
        if len(members) != len(columns):
            return False
        for a in range(len(members)):
            for b in range(a + 1, len(members)):
                c = abs(sum(x * y for x, y in zip(units[members[a]], units[members[b]])))
                if c > tol:
                    return False
    return True


def _judge_axes(answer, typed, rules):
    tol = 0.5 * 10.0 ** (1 - rules["sigfigs"]) if rules.get("sigfigs") else answer["rel_tol"]
    rows = [typed[3 * i:3 * i + 3] for i in range(3)]
    columns = [[typed[3 * r + c] for r in range(3)] for c in range(3)]
    if _axes_right(columns, answer, tol) or _axes_right(rows, answer, tol):
        return 1, "correct (each axis up to sign, in any order)"
    return 0, ("incorrect: these are not the principal axes (each vector must be an axis of "
               "the inertia tensor, every axis there once)")


def _on_keys_turns(answer, typed, rules):
    # Euler angles are the same up to whole turns (psi = 340 degrees is the key's -20): whether
    # the typed values are right so, and the entries whole turns off, named; for the feedback,
    # the values with each entry one turn off (or right whole turns off) moved to the key's
    # range. (wobble check does the same.)
    values, moved, every = list(typed), [], True
    for i, (t, k) in enumerate(zip(typed, answer["value"])):
        turns = round((t - k) / (2 * math.pi))
        there = t - turns * 2 * math.pi
        # Significant figures are of the number typed, in its range; a relative tolerance of the
        # angle in the key's range.
        right = (_close(t, k + turns * 2 * math.pi, rules, answer) if rules.get("sigfigs")
                 else _close(there, k, rules, answer))
        every = every and right
        if abs(turns) == 1:
            values[i] = there
        if turns != 0 and right:
            values[i] = k  # right: the feedback is about the other entries
            moved.append(_entry_name(answer, i))
    # Only where every entry is then within a quarter turn of the key's (1000 times 40 degrees
    # is 40 again, yet a power of ten off): else the feedback sees what was typed.
    if any(abs(v - k) > math.pi / 2 for v, k in zip(values, answer["value"])):
        values = list(typed)
    return every and bool(moved), values, moved


def judge(answer, typed, rules):
    """(score, message) for the typed values (a flat list, the key's order)."""
    if answer["kind"] == "principal_axes":
        return _judge_axes(answer, typed, rules)
    compare = sorted(typed) if answer["kind"] == "principal_moments" else list(typed)
    if _all_close(compare, answer["value"], rules, answer):
        return 1, "correct"
    right, turned, moved = (_on_keys_turns(answer, compare, rules) if answer.get("whole_turns")
                            else (False, compare, []))
    if right:
        names = " and ".join([", ".join(moved[:-1]), moved[-1]] if len(moved) > 1 else moved)
        return 1, "correct (%s %s from the key's by whole turns: the same angle%s)" % (
            names, "differs" if len(moved) == 1 else "differ", "" if len(moved) == 1 else "s")
    # A known mistake from what was typed; else how far off, an angle one turn off judged from
    # the key's range.
    for mistake in answer["mistakes"]:
        if _all_close(compare, mistake["values"], rules, answer):
            return 0, "incorrect: " + mistake["message"]
    return 0, "incorrect: " + "; ".join(_how_far(answer, turned, rules))


def _flat(submitted):
    """The submitted value as a flat list of floats, or None."""
    if isinstance(submitted, dict) and "_value" in submitted:  # pl.to_json of an ndarray
        submitted = submitted["_value"]
    if isinstance(submitted, (int, float)) and not isinstance(submitted, bool):
        return [float(submitted)]
    if isinstance(submitted, list):
        out = []
        for row in submitted:
            inner = _flat(row)
            if inner is None:
                return None
            out.extend(inner)
        return out
    return None


def grade(data):
    table = _variants(data)
    number = data["params"]["variant"]
    variant = next(v for v in table["variants"] if v["number"] == number)
    total = 0.0
    for answer in variant["answers"]:
        name = answer["input"]
        typed = _flat(data["submitted_answers"].get(name))
        if typed is None or len(typed) != len(answer["value"]):
            score, message = 0, "no answer"
        else:
            score, message = judge(answer, typed, table["rules"])
        data["partial_scores"][name] = {"score": score, "weight": 1}
        data["feedback"][name] = message
        total += score
    data["score"] = total / max(1, len(variant["answers"]))
