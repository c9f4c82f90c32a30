#!/usr/bin/env python3
"""`orthoray solve --json` against spec_oracle.py on seeded random scenes.

The scenes are drawn here, with Python's own generator (not `orthoray
generate`), on a small grid of coordinates with halves, so that what the
spec pins down precisely comes up often: corners and edges, elements that
touch, overlap or cross, starts and targets on elements, one-sided elements
seen from their back, splitters beside mirrors, diagonals meeting axis
elements, closed boxes that make cycles. Each scene is solved by the
command line (its default engine) and by the oracle, and the fields the
spec fixes must be equal: answer, reason, reflections, tail and period of a
single trajectory; each target's answer, reflections and ray under
illumination; and the exit status (0 yes, 1 no).

    test_agreement.py --cli build/orthoray [--instances instances] [--scenes N]
                      [--seed S] [--keep DIR]

First the oracle itself is held to the hand-derived answers of
instances/expected.json (with --instances), so that it is anchored to more
than the program it checks. Exits 1 at the first disagreement, with the
scene written to DIR (default: the current directory) and both answers
printed.
"""

import argparse
import json
import os
import random
import subprocess
import sys
from fractions import Fraction

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import spec_oracle  # noqa: E402


def number(rng):
    """A coordinate in [-1, 7]: mostly integers, sometimes a half."""
    n = rng.randint(-2, 14)
    return Fraction(n, 2) if rng.random() < 0.25 else Fraction(n // 2)


def text(x):
    return str(x.numerator) if x.denominator == 1 else f"{x.numerator}/{x.denominator}"


def interval(rng):
    lo = number(rng)
    return lo, lo + rng.choice([Fraction(1, 2), 1, 2, 3, 5])


def axis_element(rng, dim, kinds):
    kind = rng.choice(kinds)
    axis = rng.randrange(dim)
    sign = rng.choice(["+", "-"]) if rng.random() < 0.25 else ""
    words = [kind, "xyz"[axis] + sign, text(number(rng))]
    for j in range(dim):
        if j != axis:
            lo, hi = interval(rng)
            words += ["xyz"[j], text(lo), text(hi)]
    return " ".join(words)


def diagonal_element(rng, kinds):
    kind = rng.choice(kinds)
    x0, y0 = number(rng), number(rng)
    length = rng.choice([Fraction(1, 2), 1, 2, 3])
    if rng.random() < 0.5:
        return f"{kind} / {text(x0)} {text(y0)} {text(x0 + length)} {text(y0 + length)}"
    return f"{kind} \\ {text(x0)} {text(y0 + length)} {text(x0 + length)} {text(y0)}"


def box(dim):
    """The closed mirror box [-1, 7]^dim: rays inside it cycle or stop."""
    lines = []
    for axis in range(dim):
        for offset in ("-1", "7"):
            words = ["mirror", "xyz"[axis], offset]
            for j in range(dim):
                if j != axis:
                    words += ["xyz"[j], "-1", "7"]
            lines.append(" ".join(words))
    return lines


def scene(rng):
    dim = 2 if rng.random() < 0.7 else 3
    illumination = rng.random() < 0.5
    kinds = ["mirror"] * 6 + ["absorber"] + (["splitter"] * 3 if illumination else [])
    lines = [f"dim {dim}"]
    if rng.random() < 0.6:
        lines += box(dim)
    for _ in range(rng.randint(1, 7)):
        if dim == 2 and rng.random() < 0.25:
            lines.append(diagonal_element(rng, kinds))
        else:
            lines.append(axis_element(rng, dim, kinds))
    rays = rng.randint(1, 2) if illumination else 1
    targets = rng.randint(1, 3) if illumination else 1
    for _ in range(rays):
        start = [number(rng) for _ in range(dim)]
        direction = [0] * dim
        while not any(direction):
            direction = [rng.choice([-2, -1, -1, 0, 1, 1, 2]) for _ in range(dim)]
        lines.append("ray " + " ".join(text(x) for x in start) + " " +
                     " ".join(str(x) for x in direction))
    for _ in range(targets):
        target = on_path(rng, "\n".join(lines) + "\n") if rng.random() < 0.6 else None
        if target is None:
            target = [number(rng) for _ in range(dim)]
        lines.append("target " + " ".join(text(x) for x in target))
    return "\n".join(lines) + "\n"


def on_path(rng, partial):
    """A point on some branch of the last ray: a few events along (traced
    by the oracle, taking a random way out at each split), then part way
    along that segment. Without such targets nearly every target would be
    missed, and hits after many reflections never drawn."""
    dim, elements, rays, _ = spec_oracle.parse(partial)
    p, v = rays[-1]
    for _ in range(rng.choice([0, 0, 1, 2, 3, 5, 8, 13])):
        e = spec_oracle.event(dim, elements, p, v)
        if e is None or e[2]:
            break
        p, v = e[0], rng.choice(e[1])[0]
    e = spec_oracle.event(dim, elements, p, v)
    # On the segment to the next event (its end included), or on the ray to
    # infinity.
    fraction = rng.choice([Fraction(0), Fraction(1, 3), Fraction(1, 2), Fraction(1)])
    if e is None:
        return [p[j] + (1 + 2 * fraction) * v[j] for j in range(dim)]
    q = e[0]
    return [p[j] + fraction * (q[j] - p[j]) for j in range(dim)]


def spec_fields(answer, oracle):
    """The fields of `answer` that the spec fixes, for a scene the oracle
    answered with `oracle`: per target under illumination, else the single
    trajectory's count (and tail and period for a cycle)."""
    keys = ["answer", "reason"]
    keys += ["targets"] if "targets" in oracle else \
        [k for k in ("reflections", "tail", "period") if k in oracle]
    # With a target unlit every reachable state was explored, so `states`
    # is the reachable set's size; a search that lights every target may
    # stop before that, at a point no other search need share.
    if "states" in oracle and oracle["answer"] == "no":
        keys.append("states")
    return {k: answer.get(k) for k in keys}


def oracle_matches_instances(directory):
    """The oracle on every .scene of expected.json, against its hand-derived
    answer there."""
    with open(os.path.join(directory, "expected.json")) as f:
        expected = json.load(f)
    checked = 0
    for name, want in expected.items():
        if not name.endswith(".scene"):
            continue
        with open(os.path.join(directory, name)) as f:
            got = spec_oracle.solve(f.read())
        if got is None or {k: got.get(k) for k in want} != want:
            print(f"spec_oracle.py is wrong on {name}: {json.dumps(got)}, "
                  f"expected.json says {json.dumps(want)}")
            return False
        checked += 1
    print(f"spec_oracle.py agrees with the {checked} hand-derived answers of expected.json")
    return checked > 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", required=True, nargs="+",
                        help="the command line, with any leading words (an interpreter)")
    parser.add_argument("--instances", help="a directory with expected.json")
    parser.add_argument("--scenes", type=int, default=1500)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--keep", default=".")
    args = parser.parse_args()

    if args.instances and not oracle_matches_instances(args.instances):
        return 1
    rng = random.Random(args.seed)
    compared = skipped = 0
    tally = {}
    for n in range(args.scenes):
        text_of_scene = scene(rng)
        oracle = spec_oracle.solve(text_of_scene)
        if oracle is None:
            skipped += 1  # too long for the oracle
            continue
        run = subprocess.run(args.cli + ["solve", "-", "--json", "--timeout", "60"],
                             input=text_of_scene, capture_output=True, text=True)
        want, got, status = spec_fields(oracle, oracle), None, run.returncode
        try:
            got = spec_fields(json.loads(run.stdout), oracle)
        except json.JSONDecodeError:
            pass
        want_status = 0 if oracle["answer"] == "yes" else 1
        if got != want or status != want_status:
            path = os.path.join(args.keep, f"disagreement-{args.seed}-{n}.scene")
            with open(path, "w") as f:
                f.write(text_of_scene)
            print(f"scene {n} (seed {args.seed}), written to {path}:\n{text_of_scene}")
            print(f"spec_oracle.py: {json.dumps(want)}, exit {want_status}")
            print(f"orthoray:       {json.dumps(got)}, exit {status}\n{run.stderr}")
            return 1
        compared += 1
        key = oracle["reason"]
        tally[key] = tally.get(key, 0) + 1
    summary = ", ".join(f"{tally[k]} {k}" for k in sorted(tally))
    print(f"{compared} scenes agree with the spec oracle ({summary}); "
          f"{skipped} too long for the oracle")
    # A run that compared almost nothing proves nothing.
    return 0 if compared >= 0.9 * args.scenes and len(tally) >= 6 else 1


if __name__ == "__main__":
    sys.exit(main())
