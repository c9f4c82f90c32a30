"""An answer to `orthoray solve`, worked out from the three pages of the
specification alone (semantics.md, optics.md, octagonal.md), in Python's
exact fractions.

It shares nothing with the C++ engines: not the reader, not the lattice, not
the acting rule, not the search. Every event is found by trying every
element, every state ever reached is kept in a dict, and the least
reflections come from a plain Dijkstra over all states. So it is slow and
needs memory growing with the states, which the C++ engines must not; on
the small scenes of test_agreement.py that costs nothing, and an answer
that both arrive at independently is unlikely to share a misreading.

`solve(text)` returns the fields `orthoray solve --json` must print, or
None when the scene is too long for this oracle (more than `max_events`
events or `max_states` states).
"""

from fractions import Fraction
import heapq

AXES = {"x": 0, "y": 1, "z": 2}


def parse(text):
    """The scene as lists: (dim, elements, rays, targets). Assumes valid
    input, as written by test_agreement.py."""
    dim, elements, rays, targets = None, [], [], []
    for raw in text.splitlines():
        words = raw.split("#")[0].split()
        if not words:
            continue
        head = words[0]
        if head == "dim":
            dim = int(words[1])
        elif head in ("mirror", "absorber", "splitter") and words[1] in ("/", "\\"):
            x0, y0, x1, y1 = (Fraction(w) for w in words[2:6])
            elements.append({"kind": head, "slope": words[1], "x0": x0, "y0": y0, "x1": x1})
        elif head in ("mirror", "absorber", "splitter"):
            axis = words[1]
            side = 0
            if axis[-1] in "+-":
                side = 1 if axis[-1] == "+" else -1
                axis = axis[:-1]
            extent = {}
            for i in range(3, len(words), 3):
                extent[AXES[words[i]]] = (Fraction(words[i + 1]), Fraction(words[i + 2]))
            elements.append({"kind": head, "axis": AXES[axis], "side": side,
                             "offset": Fraction(words[2]), "extent": extent})
        elif head == "ray":
            numbers = [Fraction(w) for w in words[1:]]
            rays.append((tuple(numbers[:dim]), tuple(numbers[dim:])))
        elif head == "target":
            targets.append(tuple(Fraction(w) for w in words[1:]))
    return dim, elements, rays, targets


def axis_hit(e, p, v):
    """t > 0 where the ray meets axis element e and e acts on it, else None.
    optics.md: it acts when q lies on it (edges included), v_k != 0, and it
    is two-sided or its sign names the side the ray arrives from."""
    k = e["axis"]
    if v[k] == 0:
        return None
    if e["side"] == 1 and not v[k] < 0:
        return None
    if e["side"] == -1 and not v[k] > 0:
        return None
    t = (e["offset"] - p[k]) / v[k]
    if t <= 0:
        return None
    for j, (lo, hi) in e["extent"].items():
        if not lo <= p[j] + t * v[j] <= hi:
            return None
    return t


def diagonal_hit(e, p, v):
    """t > 0 where the ray meets diagonal element e (octagonal.md: on the
    closed segment, v not parallel to it), else None."""
    if e["slope"] == "/":
        if v[0] == v[1]:
            return None
        # y - x is constant along the segment.
        t = ((e["y0"] - e["x0"]) - (p[1] - p[0])) / (v[1] - v[0])
    else:
        if v[0] == -v[1]:
            return None
        # x + y is constant along it.
        t = ((e["x0"] + e["y0"]) - (p[0] + p[1])) / (v[0] + v[1])
    if t <= 0 or not e["x0"] <= p[0] + t * v[0] <= e["x1"]:
        return None
    return t


def event(dim, elements, p, v):
    """The next event from p along v: (point, [(direction, reflects)],
    absorbed), or None when the ray escapes."""
    best, acting = None, []
    for e in elements:
        t = diagonal_hit(e, p, v) if "slope" in e else axis_hit(e, p, v)
        if t is None:
            continue
        if best is None or t < best:
            best, acting = t, [e]
        elif t == best:
            acting.append(e)
    if best is None:
        return None
    q = tuple(p[j] + best * v[j] for j in range(dim))
    if any(e["kind"] == "absorber" for e in acting):
        return q, [], True
    back = tuple(-x for x in v)
    if any("slope" in e for e in acting):
        # octagonal.md: with another orientation acting too, back along -v;
        # one slope alone acts like one axis.
        if len({e.get("slope", e.get("axis")) for e in acting}) > 1:
            return q, [(back, True)], False
        turned = (v[1], v[0]) if acting[0]["slope"] == "/" else (-v[1], -v[0])
        if any(e["kind"] == "mirror" for e in acting):
            return q, [(turned, True)], False
        return q, [(v, False), (turned, True)], False
    # optics.md, Motion: reflecting axes R, splitting axes S; every F with
    # R <= F <= R + S negated.
    reflecting = {e["axis"] for e in acting if e["kind"] == "mirror"}
    splitting = sorted({e["axis"] for e in acting if e["kind"] == "splitter"} - reflecting)
    out = []
    for mask in range(1 << len(splitting)):
        flipped = reflecting | {a for i, a in enumerate(splitting) if mask >> i & 1}
        d = tuple(-v[j] if j in flipped else v[j] for j in range(dim))
        out.append((d, d != v))
    return q, out, False


def passes(target, p, v, q, dim):
    """Whether target lies on the closed segment from p to q (to infinity
    when q is None), p moving along v."""
    t = None
    for j in range(dim):
        if v[j] == 0:
            if target[j] != p[j]:
                return False
        else:
            tj = (target[j] - p[j]) / v[j]
            if t is None:
                t = tj
            elif tj != t:
                return False
    if t < 0:
        return False
    if q is None:
        return True
    j = next(j for j in range(dim) if v[j] != 0)
    return t <= (q[j] - p[j]) / v[j]


def single(dim, elements, ray, target, max_events):
    """semantics.md and optics.md's single trajectory: s_i is the state
    after event i; a cycle is found at the first repeat, mu and lambda as
    optics.md defines them."""
    p, v = ray
    seen = {}
    for i in range(max_events + 1):
        e = event(dim, elements, p, v)
        q = None if e is None else e[0]
        if passes(target, p, v, q, dim):
            return {"answer": "yes", "reason": "hit", "reflections": i}
        if e is None:
            return {"answer": "no", "reason": "escape", "reflections": i}
        q, out, absorbed = e
        if absorbed:
            return {"answer": "no", "reason": "absorbed", "reflections": i}
        p, v = q, out[0][0]
        if (p, v) in seen:
            mu = seen[(p, v)]
            period = i + 1 - mu
            return {"answer": "no", "reason": "cycle", "reflections": mu - 1 + period,
                    "tail": mu - 1, "period": period}
        seen[(p, v)] = i + 1
    return None


def illumination(dim, elements, rays, targets, max_states):
    """optics.md's illumination: Dijkstra over every state with labels
    (reflections, ray); a target's label is the least over the segments
    passing it."""
    label, queue, settled = {}, [], set()
    for r, start in enumerate(rays, 1):
        if start not in label or (0, r) < label[start]:
            label[start] = (0, r)
            heapq.heappush(queue, ((0, r), start))
    best = [None] * len(targets)
    while queue:
        here, state = heapq.heappop(queue)
        if state in settled or label[state] != here:
            continue
        settled.add(state)
        if len(settled) > max_states:
            return None
        p, v = state
        e = event(dim, elements, p, v)
        q = None if e is None else e[0]
        for i, target in enumerate(targets):
            if passes(target, p, v, q, dim) and (best[i] is None or here < best[i]):
                best[i] = here
        if e is None:
            continue
        q, out, _ = e
        for d, reflects in out:
            there = (here[0] + (1 if reflects else 0), here[1])
            if (q, d) not in label or there < label[(q, d)]:
                label[(q, d)] = there
                heapq.heappush(queue, (there, (q, d)))
    lit = all(b is not None for b in best)
    return {
        "answer": "yes" if lit else "no",
        "reason": "lit" if lit else "unlit",
        "targets": [{"target": i, "answer": "no"} if b is None else
                    {"target": i, "answer": "yes", "reflections": b[0], "ray": b[1]}
                    for i, b in enumerate(best, 1)],
        # optics.md's "distinct states explored": this search explores every
        # state reachable, rays' starts included.
        "states": len(label),
    }


def solve(text, max_events=20000, max_states=20000):
    dim, elements, rays, targets = parse(text)
    # optics.md: more than one ray or target, or any splitter, asks the
    # illumination question.
    if len(rays) == 1 and len(targets) == 1 and all(e["kind"] != "splitter" for e in elements):
        return single(dim, elements, rays[0], targets[0], max_events)
    return illumination(dim, elements, rays, targets, max_states)
