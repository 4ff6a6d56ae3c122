#!/usr/bin/env python3
"""Plots the rms error of `gpsurf fit` against its iterations, one line per log, as an SVG.

Usage: scripts/plot_fit_iterations.py OUT.svg TITLE LABEL=FIT.log [LABEL=FIT.log ...]

Each log is what `gpsurf fit` printed (scripts/fit_figures.sh keeps them); its lines
"iteration K: rms R, max M (of the diagonal), T s" are read. The y axis is logarithmic.
"""
import math
import re
import sys

LINE = re.compile(r"^iteration (\d+): rms ([0-9.eE+-]+), max ([0-9.eE+-]+)")
COLOURS = ["#1f5fbf", "#d9541e", "#2e9e44", "#8e3fbf", "#b8860b", "#444444"]
WIDTH, HEIGHT = 640, 400
LEFT, RIGHT, TOP, BOTTOM = 80, 170, 40, 50


def read_log(path):
    points = []
    with open(path, encoding="utf-8") as log:
        for line in log:
            match = LINE.match(line)
            if match:
                points.append((int(match.group(1)), float(match.group(2))))
    if not points:
        sys.exit(f"{path}: no 'iteration K: rms R, ...' lines")
    return points


def main(argv):
    if len(argv) < 4:
        sys.exit(__doc__.strip().splitlines()[2])
    out, title, series = argv[1], argv[2], []
    for spec in argv[3:]:
        label, sep, path = spec.partition("=")
        if not sep:
            sys.exit(f"'{spec}': expected LABEL=FIT.log")
        series.append((label, read_log(path)))

    last = max(k for _, points in series for k, _ in points)
    low = min(r for _, points in series for _, r in points)
    high = max(r for _, points in series for _, r in points)
    decade_low, decade_high = math.floor(math.log10(low)), math.ceil(math.log10(high))
    if decade_high == decade_low:
        decade_high += 1
    plot_w, plot_h = WIDTH - LEFT - RIGHT, HEIGHT - TOP - BOTTOM

    def x_of(k):
        return LEFT + plot_w * k / max(last, 1)

    def y_of(r):
        return TOP + plot_h * (decade_high - math.log10(r)) / (decade_high - decade_low)

    svg = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{HEIGHT}" '
           f'font-family="sans-serif" font-size="12">',
           f'<rect width="{WIDTH}" height="{HEIGHT}" fill="white"/>',
           f'<text x="{WIDTH / 2}" y="22" text-anchor="middle" font-size="14">{title}</text>']
    for decade in range(decade_low, decade_high + 1):
        y = y_of(10.0 ** decade)
        svg.append(f'<line x1="{LEFT}" y1="{y:.1f}" x2="{LEFT + plot_w}" y2="{y:.1f}" stroke="#ddd"/>')
        svg.append(f'<text x="{LEFT - 6}" y="{y + 4:.1f}" text-anchor="end">1e{decade}</text>')
    for k in range(0, last + 1):
        x = x_of(k)
        svg.append(f'<line x1="{x:.1f}" y1="{TOP + plot_h}" x2="{x:.1f}" y2="{TOP + plot_h + 4}" stroke="black"/>')
        svg.append(f'<text x="{x:.1f}" y="{TOP + plot_h + 18}" text-anchor="middle">{k}</text>')
    svg.append(f'<rect x="{LEFT}" y="{TOP}" width="{plot_w}" height="{plot_h}" fill="none" stroke="black"/>')
    svg.append(f'<text x="{LEFT + plot_w / 2}" y="{HEIGHT - 10}" text-anchor="middle">iteration</text>')
    svg.append(f'<text transform="translate(18 {TOP + plot_h / 2}) rotate(-90)" text-anchor="middle">'
               'rms distance / bbox diagonal</text>')
    for i, (label, points) in enumerate(series):
        colour = COLOURS[i % len(COLOURS)]
        path = " ".join(f"{x_of(k):.1f},{y_of(r):.1f}" for k, r in points)
        svg.append(f'<polyline points="{path}" fill="none" stroke="{colour}" stroke-width="2"/>')
        for k, r in points:
            svg.append(f'<circle cx="{x_of(k):.1f}" cy="{y_of(r):.1f}" r="3" fill="{colour}"/>')
        y = TOP + 10 + 20 * i
        svg.append(f'<line x1="{LEFT + plot_w + 12}" y1="{y}" x2="{LEFT + plot_w + 36}" y2="{y}" '
                   f'stroke="{colour}" stroke-width="2"/>')
        svg.append(f'<text x="{LEFT + plot_w + 42}" y="{y + 4}">{label}</text>')
    svg.append("</svg>")
    with open(out, "w", encoding="utf-8") as file:
        file.write("\n".join(svg) + "\n")


if __name__ == "__main__":
    main(sys.argv)
