#!/usr/bin/env python3
"""Mechanical checks of an SVG figure written by shadecalc (tests/e2e/test_figures.sh):

  - every text's box (its length at 0.6 em a character, the font's size high) lies inside the
    viewBox, rotated labels included;
  - every point of a curve, a marker or a cell that is not clipped lies inside the viewBox;
  - every legend text lies inside the legend's box;
  - no two curves share a style (colour and dash pattern), so curves that coincide stay
    distinguishable.

Prints one line per problem and exits 1 if there is any."""
import re
import sys
import xml.etree.ElementTree as ET

SVG = "{http://www.w3.org/2000/svg}"
CHAR_EM = 0.6


def text_box(t, size):
    x, y = float(t.get("x")), float(t.get("y"))
    width = CHAR_EM * size * len(("".join(t.itertext())))
    anchor = t.get("text-anchor", "start")
    left = x - width / 2 if anchor == "middle" else x - width if anchor == "end" else x
    box = (left, y - size, left + width, y + 0.25 * size)
    m = re.match(r"rotate\((-?[\d.]+) ([\d.]+) ([\d.]+)\)", t.get("transform", ""))
    if m:  # a quarter turn about (cx, cy): swap the box's extents about that point
        cx, cy = float(m.group(2)), float(m.group(3))
        x0, y0, x1, y1 = box
        box = (cx - (y1 - cy), cy + (x0 - cx), cx - (y0 - cy), cy + (x1 - cx))
        box = (min(box[0], box[2]), min(box[1], box[3]), max(box[0], box[2]), max(box[1], box[3]))
    return box


def inside(box, outer, slack=0.5):
    return (box[0] >= outer[0] - slack and box[1] >= outer[1] - slack and
            box[2] <= outer[2] + slack and box[3] <= outer[3] + slack)


def font_size(node, parents, default):
    while node is not None:
        if node.get("font-size"):
            return float(node.get("font-size"))
        node = parents.get(node)
    return default


def clipped(node, parents):
    while node is not None:
        if node.get("clip-path"):
            return True
        node = parents.get(node)
    return False


def check(path):
    root = ET.parse(path).getroot()
    parents = {c: p for p in root.iter() for c in p}
    vb = [float(v) for v in root.get("viewBox").split()]
    view = (vb[0], vb[1], vb[0] + vb[2], vb[1] + vb[3])
    base = float(root.get("font-size", "12"))
    problems = []
    for t in root.iter(SVG + "text"):
        box = text_box(t, font_size(t, parents, base))
        if not inside(box, view):
            problems.append("text %r at %s outside the viewBox %s" % ("".join(t.itertext()), box, view))
    for p in root.iter(SVG + "polyline"):
        if clipped(p, parents):
            continue
        for xy in p.get("points").split():
            x, y = (float(v) for v in xy.split(","))
            if not inside((x, y, x, y), view):
                problems.append("point %s,%s outside the viewBox" % (x, y))
    for r in root.iter(SVG + "rect"):
        x, y = float(r.get("x", 0)), float(r.get("y", 0))
        box = (x, y, x + float(r.get("width")), y + float(r.get("height")))
        if not inside(box, view):
            problems.append("rect %s outside the viewBox" % (box,))
    for legend in (g for g in root.iter(SVG + "g") if g.get("class") == "legend"):
        frame = legend.find(SVG + "rect")
        fx, fy = float(frame.get("x")), float(frame.get("y"))
        fbox = (fx, fy, fx + float(frame.get("width")), fy + float(frame.get("height")))
        for t in legend.iter(SVG + "text"):
            if not inside(text_box(t, font_size(t, parents, base)), fbox):
                problems.append("legend text %r outside the legend's box" % "".join(t.itertext()))
    styles = {}
    for g in (g for g in root.iter(SVG + "g") if g.get("class") == "series"):
        line = g.find(SVG + "polyline")
        style = (g.get("stroke"), line.get("stroke-dasharray") if line is not None else "")
        if style in styles:
            problems.append("curves %r and %r share the style %s" % (styles[style], g.get("data-label"), style))
        styles[style] = g.get("data-label")
    for p in problems:
        print("%s: %s" % (path, p))
    return not problems


if __name__ == "__main__":
    sys.exit(0 if all([check(p) for p in sys.argv[1:]]) else 1)
