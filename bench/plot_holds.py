#!/usr/bin/env python3
"""Time per simulated second against largest strain, one colour per candidate, from holds CSVs.

Usage: bench/plot_holds.py OUT.svg LABEL=holds_a.csv LABEL=holds_b.csv ...
Reads the `grid` rows of each CSV (clothbench --mode holds); x: seconds of run time per simulated
second (ms per frame x 60 / 1000), y: largest structural strain while swinging; both on log axes.
Lines at the limit + 5 % (0.15) and the tear threshold (0.35). Plain SVG, no plotting library.
"""
import csv
import math
import sys

COLOURS = ["#d62728", "#ff7f0e", "#1f77b4", "#2ca02c", "#9467bd", "#8c564b"]
W, H, L, R, T, B = 860, 480, 70, 290, 30, 55  # size and margins


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out = sys.argv[1]
    series = []
    for arg in sys.argv[2:]:
        label, _, path = arg.partition("=")
        pts = []
        with open(path, newline="") as f:
            for row in csv.DictReader(f):
                if row["table"] != "grid":
                    continue
                x = float(row["ms_per_frame"]) * 60 / 1000
                y = float(row["strain_swing"])
                if x > 0 and y > 0 and math.isfinite(y):
                    pts.append((x, min(y, 100.0), int(row["tears"]) > 0))
        series.append((label, pts))
    xs = [p[0] for _, s in series for p in s]
    x0, x1 = math.floor(math.log10(min(xs))), math.ceil(math.log10(max(xs)))
    y0, y1 = -2, 1  # strain 0.01 .. 10

    def px(x):
        return L + (math.log10(x) - x0) / (x1 - x0) * (W - L - R)

    def py(y):
        return H - B - (math.log10(y) - y0) / (y1 - y0) * (H - T - B)

    svg = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="12">',
           f'<rect width="{W}" height="{H}" fill="white"/>']
    for e in range(x0, x1 + 1):
        svg.append(f'<line x1="{px(10**e):.1f}" y1="{T}" x2="{px(10**e):.1f}" y2="{H-B}" stroke="#ddd"/>')
        svg.append(f'<text x="{px(10**e):.1f}" y="{H-B+16}" text-anchor="middle">{10**e:g}</text>')
    for e in range(y0, y1 + 1):
        svg.append(f'<line x1="{L}" y1="{py(10**e):.1f}" x2="{W-R}" y2="{py(10**e):.1f}" stroke="#ddd"/>')
        svg.append(f'<text x="{L-6}" y="{py(10**e)+4:.1f}" text-anchor="end">{10**e:g}</text>')
    for y, name in ((0.15, "limit + 5 %"), (0.35, "tear threshold")):
        svg.append(f'<line x1="{L}" y1="{py(y):.1f}" x2="{W-R}" y2="{py(y):.1f}" stroke="#888" stroke-dasharray="4 3"/>')
        svg.append(f'<text x="{W-R-4}" y="{py(y)-4:.1f}" text-anchor="end" fill="#555">{name}</text>')
    svg.append(f'<text x="{(L+W-R)/2}" y="{H-12}" text-anchor="middle">run time per simulated second (s, one thread)</text>')
    svg.append(f'<text x="16" y="{(T+H-B)/2}" text-anchor="middle" transform="rotate(-90 16 {(T+H-B)/2})">largest strain while swinging</text>')
    for i, (label, pts) in enumerate(series):
        c = COLOURS[i % len(COLOURS)]
        for x, y, tore in pts:
            if tore:  # a cross: this case tore
                svg.append(f'<path d="M{px(x)-4:.1f},{py(y)-4:.1f}l8,8m0,-8l-8,8" stroke="{c}" stroke-width="1.6"/>')
            else:
                svg.append(f'<circle cx="{px(x):.1f}" cy="{py(y):.1f}" r="3.5" fill="{c}" fill-opacity="0.75"/>')
        ly = T + 16 + 20 * i
        svg.append(f'<circle cx="{W-R+16}" cy="{ly-4}" r="4" fill="{c}"/><text x="{W-R+26}" y="{ly}">{label}</text>')
    ly = T + 16 + 20 * len(series)
    svg.append(f'<text x="{W-R+10}" y="{ly+6}" fill="#555">x: the case tore</text>')
    svg.append("</svg>")
    with open(out, "w") as f:
        f.write("\n".join(svg) + "\n")


if __name__ == "__main__":
    main()
