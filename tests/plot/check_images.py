#!/usr/bin/python3
"""Plots read back by independent decoders: PNG with Pillow (python3-pil), SVG with xml.etree.

    /usr/bin/python3 tests/plot/check_images.py --saasgaps build/saasgaps --examples schemas/examples

Solves report problem 3 case 1 and the shrink-fit rings with the saasgaps binary, draws contour,
closure and convergence plots with `saasgaps plot`, and checks:
  PNG: decodes, has the requested size, and many distinct colours (bands, antialiased text);
  SVG: parses; has the requested size; holds glyph uses (the labels' text) and paths of several
       colours; for contour plots, a colour bar (a column of equal filled rectangles stacked without
       gaps, each its own colour) and the colour bands (distinct fill colours); with --mesh, a
       stroked path with a subpath per solid element.
"""

import json
import pathlib
import re
import sys
import tempfile
import xml.etree.ElementTree as ET

from PIL import Image

SVG = "{http://www.w3.org/2000/svg}"
from checking import arguments, check, failures, run


def check_png(path, width, height):
    with Image.open(path) as image:
        check(image.format == "PNG", f"{path.name}: not a PNG")
        check(image.size == (width, height), f"{path.name}: size {image.size}, expected {(width, height)}")
        colours = image.convert("RGB").getcolors(maxcolors=1 << 20)
        check(colours is not None and len(colours) > 30, f"{path.name}: only {len(colours or [])} colours")


def style_of(element):
    return dict(item.split(":", 1) for item in element.get("style", "").split(";") if ":" in item)


def rectangle(d):
    """(x, y, w, h) when the path data is one axis-aligned rectangle, else None."""
    numbers = [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?(?:e[-+]?\d+)?", d)]
    commands = re.findall(r"[A-Za-z]", d)
    if commands[:5] != ["M", "L", "L", "L", "Z"] or len(numbers) < 8:
        return None
    xs, ys = numbers[0:8:2], numbers[1:8:2]
    if len(set(xs)) != 2 or len(set(ys)) != 2:
        return None
    return min(xs), min(ys), max(xs) - min(xs), max(ys) - min(ys)


def drawing_paths(root):
    """The <path> elements outside <defs> (those in <defs> are glyph outlines)."""
    glyphs = {id(p) for d in root.iter(SVG + "defs") for p in d.iter(SVG + "path")}
    return [p for p in root.iter(SVG + "path") if id(p) not in glyphs]


def check_svg(path, width, height, bands_expected=False, mesh_elements=0):
    root = ET.parse(path).getroot()
    check(root.tag == SVG + "svg", f"{path.name}: root is {root.tag}")
    check(root.get("width") == f"{width}px" and root.get("height") == f"{height}px",
          f"{path.name}: size {root.get('width')} x {root.get('height')}")
    uses = list(root.iter(SVG + "use"))
    check(len(uses) > 100, f"{path.name}: only {len(uses)} glyphs: labels missing")
    paths = drawing_paths(root)
    fills = {style_of(p).get("fill") for p in paths if style_of(p).get("fill", "none") != "none"}
    strokes = {style_of(p).get("stroke") for p in paths if style_of(p).get("stroke", "none") != "none"}
    check(len(fills) + len(strokes) >= 4, f"{path.name}: only {len(fills)} fill and {len(strokes)} line colours")
    if bands_expected:
        check(len(fills) >= 8, f"{path.name}: only {len(fills)} fill colours: colour bands missing")
        # The colour bar: rectangles of one x and width, stacked edge to edge, each its own colour.
        columns = {}
        for p in paths:
            r = rectangle(p.get("d", ""))
            fill = style_of(p).get("fill", "none")
            if r and fill != "none":
                columns.setdefault((round(r[0], 2), round(r[2], 2)), []).append((r[1], r[3], fill))
        best = max(columns.values(), key=len, default=[])
        best.sort()
        stacked = all(abs(a[0] + a[1] - b[0]) < 0.01 for a, b in zip(best, best[1:]))
        check(len(best) >= 5 and stacked and len({f for _, _, f in best}) == len(best),
              f"{path.name}: no colour bar (best column of rectangles: {len(best)})")
    if mesh_elements:
        stroked = [p for p in paths if style_of(p).get("stroke", "none") != "none"]
        subpaths = max((p.get("d", "").count("M") for p in stroked), default=0)
        check(subpaths >= mesh_elements,
              f"{path.name}: the mesh path has {subpaths} subpaths for {mesh_elements} elements")


def main():
    args = arguments(__doc__)
    with tempfile.TemporaryDirectory(prefix="saasgaps-images-") as tmp:
        out = pathlib.Path(tmp)
        models = {"p3": "report-problem3-case1.json", "ring": "ring-shrink-fit-plane-strain.json"}
        for name, model in models.items():
            run(args.saasgaps, "solve", str(args.examples / model), "-q", "-o", str(out / f"{name}.json"))
        elements = {name: len(json.loads((out / f"{name}.json").read_text())["elements"]) for name in models}

        plots = [  # result, field, extra options, size, contour?
            ("p3", "effective", ["--deformed", "50", "--mesh"], (1000, 600), True),
            ("p3", "sigma_r", [], (800, 500), True),
            ("ring", "sigma_theta", ["--mesh"], (900, 700), True),
            ("ring", "temperature", ["--levels", "even"], (700, 700), True),
            ("ring", "displacement", ["--deformed", "auto"], (900, 700), True),
            ("p3", "closure", [], (900, 600), False),
            ("ring", "closure", ["--along", "position"], (900, 600), False),
            ("p3", "convergence", [], (800, 600), False),
        ]
        for result, field, extra, (w, h), contour in plots:
            for suffix in ("png", "svg"):
                image = out / f"{result}-{field}.{suffix}"
                run(args.saasgaps, "plot", str(out / f"{result}.json"), "--field", field, *extra,
                    "--width", str(w), "--height", str(h), "-o", str(image))
                if suffix == "png":
                    check_png(image, w, h)
                else:
                    check_svg(image, w, h, bands_expected=contour,
                              mesh_elements=elements[result] if "--mesh" in extra else 0)
    if failures:
        sys.exit(f"{len(failures)} check(s) failed")
    print("all image checks passed")


if __name__ == "__main__":
    main()
