#!/usr/bin/python3
"""Plots decoded as images and compared with the result document (Pillow, python3-pil).

    /usr/bin/python3 tests/plot/check_decoded.py --saasgaps build/saasgaps --examples schemas/examples

Solves report problem 3 case 1 with a units block added, and the shrink-fit rings without one, and
checks:
  the result document: `units` as the model names them (absent when it names none); every gap's
    contact_pressure = max(0, -sigma_m), exactly;
  the closure plot's table holds every iteration's closures, exactly as the history rows do;
  the contact-pressure plot: its data table (.csv) holds the result's contact pressures and
    closures exactly; in the PNG, a marker of the pressure curve's colour sits at each point's px,
    the y tick marks sit where the table says, and each marker's height is its value on that axis;
  a contour plot: a frame with tick marks at even spacing on its bottom and left edges (the r, z
    axes), and band colours on the viridis curve (sampled independently at fifths), both ends used;
    the same check rejects the rainbow map (the check can fail);
  a field along a path: every sample lies in the element it names, and its value is the recovered
    stresses (each element's material side) interpolated there as the report's element does
    (linear on the triangle of two corners and the centre, the centre the mean of the corners), the
    von Mises stress of the interpolated components, to 1e-9.
"""

import csv
import json
import math
import pathlib
import sys
import tempfile

import numpy
from PIL import Image

from checking import arguments, check, failures, run

# matplotlib's viridis at 0, 0.2, .., 1 (a different sampling from the plot library's tenths).
VIRIDIS_FIFTHS = [(68, 1, 84), (64, 67, 135), (41, 120, 142), (34, 167, 132), (121, 209, 81), (253, 231, 36)]
PRESSURE_COLOUR = (191, 26, 26)  # the contact pressure curve, (0.75, 0.10, 0.10)
UNITS = {"length": "in", "force": "lbf", "stress": "psi", "temperature": "degF"}


def distance_to_polyline(colour, stops):
    """Euclidean distance (0..1 per channel) from colour to the polyline through stops."""
    c = [v / 255 for v in colour]
    best = math.inf
    for a, b in zip(stops, stops[1:]):
        a = [v / 255 for v in a]
        b = [v / 255 for v in b]
        ab = [y - x for x, y in zip(a, b)]
        t = max(0.0, min(1.0, sum((ci - ai) * d for ci, ai, d in zip(c, a, ab)) / sum(d * d for d in ab)))
        best = min(best, math.dist(c, [ai + t * d for ai, d in zip(a, ab)]))
    return best


def band_colours(image):
    """Colours that fill areas and are not greys: the contour bands. A pixel counts when its four
    neighbours have its colour (antialiased edges and seams, one pixel wide, do not)."""
    a = numpy.asarray(image.convert("RGB")).astype(numpy.int32)
    code = (a[:, :, 0] << 16) | (a[:, :, 1] << 8) | a[:, :, 2]
    c = code[1:-1, 1:-1]
    interior = (c == code[:-2, 1:-1]) & (c == code[2:, 1:-1]) & (c == code[1:-1, :-2]) & (c == code[1:-1, 2:])
    values, counts = numpy.unique(c[interior], return_counts=True)
    colours = [((int(v) >> 16) & 255, (int(v) >> 8) & 255, int(v) & 255) for v, n in zip(values, counts) if n >= 100]
    return [colour for colour in colours if max(colour) - min(colour) > 25]


def on_colour_map(path, stops):
    colours = band_colours(Image.open(path))
    off = [c for c in colours if distance_to_polyline(c, stops) > 0.1]
    ends = all(any(math.dist(c, end) < 8 for c in colours) for end in (stops[0], stops[-1]))
    return colours, off, ends


def dark(pixel):
    """A grey of the axes and tick marks (antialiased lines included), not white, not a colour."""
    r, g, b = pixel[:3]
    return max(r, g, b) - min(r, g, b) < 6 and r < 200


def check_axes(path):
    """A frame whose bottom and left edges carry evenly spaced tick marks outside it."""
    image = Image.open(path).convert("RGB")
    w, h = image.size
    px = image.load()
    def longest_run(flags):
        best = run_length = 0
        for f in flags:
            run_length = run_length + 1 if f else 0
            best = max(best, run_length)
        return best

    # Frame edges are unbroken dark lines (text is not).
    rows = [longest_run(dark(px[x, y]) for x in range(w)) for y in range(h)]
    cols = [longest_run(dark(px[x, y]) for y in range(h)) for x in range(w)]
    long_rows = [y for y in range(h) if rows[y] > 0.3 * w]
    long_cols = [x for x in range(w) if cols[x] > 0.3 * h]
    check(len(long_rows) >= 2 and len(long_cols) >= 2, f"{path.name}: no frame ({len(long_rows)} rows, {len(long_cols)} columns)")
    if len(long_rows) < 2 or len(long_cols) < 2:
        return
    top, bottom, left = min(long_rows), max(long_rows), min(long_cols)
    right = max(x for x in long_cols if x > left + 10)

    def clusters(positions):
        groups = []
        for p in positions:
            if groups and p - groups[-1][-1] <= 1:
                groups[-1].append(p)
            else:
                groups.append([p])
        return [sum(g) / len(g) for g in groups]

    # Tick marks: dark pixels 2-3 px below the bottom edge, and 2-3 px left of the left edge.
    below = clusters([x for x in range(left - 2, right + 3) if dark(px[x, bottom + 3])])
    beside = clusters([y for y in range(top - 2, bottom + 3) if dark(px[left - 3, y])])
    for name, ticks in (("bottom", below), ("left", beside)):
        gaps = [b - a for a, b in zip(ticks, ticks[1:])]
        even = len(gaps) >= 2 and max(gaps) - min(gaps) <= 2.0
        check(len(ticks) >= 3 and even, f"{path.name}: {name} ticks at {[round(t) for t in ticks]}: not evenly spaced")


def read_table(path):
    notes, lines = [], []
    for line in path.read_text().splitlines():
        (notes if line.startswith("# ") else lines).append(line[2:] if line.startswith("# ") else line)
    return notes, list(csv.DictReader(lines))


def check_contact(out, saasgaps, result):
    args = ["plot", str(out / "p3.json"), "--field", "contact_pressure", "--along", "position", "--width", "900",
            "--height", "700"]
    run(saasgaps, *args, "-o", str(out / "contact.png"))
    run(saasgaps, *args, "-o", str(out / "contact.csv"))
    notes, rows = read_table(out / "contact.csv")
    gaps = {g["id"]: g for g in result["gaps"]}
    check(len(rows) == len(gaps), f"contact table: {len(rows)} rows for {len(gaps)} gaps")
    for row in rows:
        gap = gaps[int(row["gap"])]
        check(float(row["contact_pressure"]) == gap["contact_pressure"],
              f"gap {row['gap']}: table {row['contact_pressure']} vs result {gap['contact_pressure']!r}")
        check(float(row["closure"]) == gap["closure"], f"gap {row['gap']}: closure")
    check(any("in psi" in n for n in notes) and any("[in]" in n for n in notes), f"contact table: units in {notes}")

    # The y axis: tick value@px pairs; a linear map from value to px.
    ticks = next(n for n in notes if n.startswith("ticks pressure:")).split(":", 1)[1].split()
    ticks = [tuple(float(v) for v in t.split("@")) for t in ticks]
    (v0, y0), (v1, y1) = ticks[0], ticks[-1]
    image = Image.open(out / "contact.png").convert("RGB")
    px = image.load()
    x_left = min(float(r["px"]) for r in rows)  # x starts at 0, the axis' left end: the frame
    for value, y in ticks:
        check(any(dark(px[round(x_left) - d, row]) for d in (2, 3, 4) for row in (math.floor(y), math.ceil(y))),
              f"contact plot: no tick mark at {value} (y {y:.1f})")
    hits = 0
    for row in rows:
        x, y = float(row["px"]), float(row["py_pressure"])
        expected_y = y0 + (float(row["contact_pressure"]) - v0) * (y1 - y0) / (v1 - v0)
        check(abs(expected_y - y) < 0.01, f"gap {row['gap']}: drawn at y {y:.2f}, its value on the axis is at {expected_y:.2f}")
        if math.dist(px[round(x), round(y)], PRESSURE_COLOUR) < 40:
            hits += 1
    check(hits == len(rows), f"contact plot: {hits} of {len(rows)} markers found at their positions")
    # A wrong value would be visible: half the largest pressure is not where the largest is drawn.
    top = min(rows, key=lambda r: float(r["py_pressure"]))
    check(float(top["contact_pressure"]) == max(g["contact_pressure"] for g in result["gaps"]),
          "the highest marker is not the largest contact pressure")


def check_closure_table(out, saasgaps, result):
    """The closure plot's table: every iteration's closures are the history rows' gap_closures."""
    run(saasgaps, "plot", str(out / "p3.json"), "--field", "closure", "-o", str(out / "closure.csv"))
    _, rows = read_table(out / "closure.csv")
    check([int(r["gap"]) for r in rows] == [g["id"] for g in result["gaps"]], "closure table: gaps in model order")
    for h in result["history"]:
        column = [float(r[f"iteration_{h['iteration']}"]) for r in rows]
        check(column == h["gap_closures"], f"closure table: iteration {h['iteration']} differs from its history row")


def inside(point, corners):
    """Point in a convex polygon (either orientation), boundary included."""
    signs = set()
    for (ax, az), (bx, bz) in zip(corners, corners[1:] + corners[:1]):
        cross = (bx - ax) * (point[1] - az) - (bz - az) * (point[0] - ax)
        if abs(cross) > 1e-12:
            signs.add(cross > 0)
    return len(signs) <= 1


STRESS_KEYS = ("sigma_r", "sigma_z", "tau_rz", "sigma_theta")


def recovered_effective(point, element, nodes, stresses, sides):
    """The von Mises stress of the recovered stresses interpolated at point in a 4-node report
    element: linear on the triangle (corner a, corner b, centre) holding it."""
    ids = element["nodes"]
    assert len(ids) == 4, "the report's examples are 4-node elements"
    values = [sides.get((n, element["material"]), stresses[n]) for n in ids]
    corners = [nodes[n] for n in ids]
    centre = (sum(c[0] for c in corners) / 4, sum(c[1] for c in corners) / 4)
    centre_value = [sum(v[k] for v in values) / 4 for k in range(4)]
    for a in range(4):
        b = (a + 1) % 4
        tri = [corners[a], corners[b], centre]
        if not inside(point, tri):
            continue
        (x0, y0), (x1, y1), (x2, y2) = tri
        det = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)
        w1 = ((point[0] - x0) * (y2 - y0) - (x2 - x0) * (point[1] - y0)) / det
        w2 = ((x1 - x0) * (point[1] - y0) - (point[0] - x0) * (y1 - y0)) / det
        w0 = 1 - w1 - w2
        s = [w0 * values[a][k] + w1 * values[b][k] + w2 * centre_value[k] for k in range(4)]
        sr, sz, trz, st = s
        return math.sqrt(((sr - sz) ** 2 + (sz - st) ** 2 + (st - sr) ** 2) / 2 + 3 * trz ** 2)
    raise AssertionError(f"{point} is in none of the triangles of element {element['id']}")


def check_path(out, saasgaps, result):
    run(saasgaps, "plot", str(out / "p3.json"), "--field", "effective", "--path", "0.1,0.9;8.9,0.1",
        "--samples", "60", "-o", str(out / "path.csv"))
    run(saasgaps, "plot", str(out / "p3.json"), "--field", "effective", "--path", "0.1,0.9;8.9,0.1",
        "--samples", "60", "-o", str(out / "path.png"))
    _, rows = read_table(out / "path.csv")
    nodes = {n["id"]: (n["r"], n["z"]) for n in result["nodes"]}
    elements = {e["id"]: e for e in result["elements"]}
    stresses = {n["id"]: [n[k] for k in STRESS_KEYS] for n in result["nodes"] if "sigma_r" in n}
    sides = {(s["node"], s["material"]): [s[k] for k in STRESS_KEYS] for s in result.get("node_sides", [])}
    check(len(rows) == 60, f"path: {len(rows)} samples")
    for row in rows:
        point = (float(row["r"]), float(row["z"]))
        if not row["element"]:
            check(not any(inside(point, [nodes[n] for n in e["nodes"]]) for e in elements.values()),
                  f"path: {point} has no element but lies in one")
            continue
        element = elements[int(row["element"])]
        check(inside(point, [nodes[n] for n in element["nodes"]]), f"path: {point} is not in element {row['element']}")
        expected = recovered_effective(point, element, nodes, stresses, sides)
        check(abs(float(row["effective"]) - expected) <= 1e-9 * max(1.0, abs(expected)),
              f"path: {point} in element {row['element']}: {row['effective']} vs {expected!r}")


def main():
    args = arguments(__doc__)
    with tempfile.TemporaryDirectory(prefix="saasgaps-decoded-") as tmp:
        out = pathlib.Path(tmp)
        model = json.loads((args.examples / "report-problem3-case1.json").read_text())
        model["units"] = UNITS
        (out / "p3-model.json").write_text(json.dumps(model))
        run(args.saasgaps, "solve", str(out / "p3-model.json"), "-q", "-o", str(out / "p3.json"))
        run(args.saasgaps, "solve", str(args.examples / "ring-shrink-fit-plane-strain.json"), "-q", "-o", str(out / "ring.json"))
        result = json.loads((out / "p3.json").read_text())
        ring = json.loads((out / "ring.json").read_text())

        check(result.get("units") == UNITS, f"result units {result.get('units')}")
        check("units" not in ring, "a model without units gives a result without them")
        for gap in result["gaps"] + ring["gaps"]:
            check(gap["contact_pressure"] == max(0.0, -gap["sigma_m"]), f"gap {gap['id']}: contact_pressure")
        check(all(g["contact_pressure"] > 0 for g in result["gaps"] if g["state"] == "closed"),
              "problem 3's closed gaps carry contact pressure")

        check_contact(out, args.saasgaps, result)
        check_closure_table(out, args.saasgaps, result)
        check_path(out, args.saasgaps, result)

        for name, extra in (("viridis", []), ("rainbow", ["--colormap", "rainbow"])):
            image = out / f"effective-{name}.png"
            run(args.saasgaps, "plot", str(out / "p3.json"), "--field", "effective", *extra, "--width", "1000",
                "--height", "600", "-o", str(image))
            colours, off, ends = on_colour_map(image, VIRIDIS_FIFTHS)
            if name == "viridis":
                check(len(colours) >= 6 and not off and ends,
                      f"default map: {len(colours)} band colours, off viridis: {off}, both ends used: {ends}")
                check_axes(image)
            else:
                check(len(off) >= 3, f"the colour map check does not tell rainbow from viridis ({off})")
        check_axes_of = out / "ring-axes.png"
        run(args.saasgaps, "plot", str(out / "ring.json"), "--field", "sigma_r", "--width", "800", "--height", "800",
            "-o", str(check_axes_of))
        check_axes(check_axes_of)
    if failures:
        sys.exit(f"{len(failures)} check(s) failed")
    print("all decoded plot checks passed")


if __name__ == "__main__":
    main()
