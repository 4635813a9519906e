#!/usr/bin/python3
"""Published error bands of the CVIU 2014 integral-invariant figures, read from the vector
plots of J. Levallois' PhD thesis (the data behind the paper's figures, same tool and
protocol): graphs/<Shape>_<quantity>_Loo.pdf in github.com/jlevallois/PhD-Thesis.

Each plot (matplotlib, PDF 1.4, Flate streams) draws, per estimator, two polylines (the band)
in log-log axes. The axes are calibrated from the major tick marks and their 10^e labels; a
polyline vertex x maps to h = exp(-i/10) with i an integer (checked), y to the error. The
legend (a short segment and its label) names the colour of the II estimator.

    scripts/extract_published_bands.py THESIS_GIT_DIR COMMIT > papers/NAME/published.csv

Output columns: figure, shape, estimator, i, h, lo, hi (the band at h = exp(-i/10)).
"""
import math
import re
import subprocess
import sys
import zlib

# (figure in the thesis, zdg shape, zdg estimator)
FIGURES_3D = [
    (f"{fig}_{q}_Loo", shape, est)
    for fig, shape in [("Sphere", "sphere9"), ("RoundedCube2", "rcube"), ("BlobbyCube", "goursat")]
    for q, est in [("Mean", "ii-mean"), ("k1", "ii-k1"), ("k2", "ii-k2")]
]
FIGURES_2D = [
    ("Ellipse_Loo", "ellipse:20,7", "ii-curvature"),
    ("Flower_Loo", "flower:20,7,6", "ii-curvature"),
    ("AccFlower_Loo", "accflower:20,5,0.60792710185402662", "ii-curvature"),
]


def page_stream(pdf):
    best = None
    for m in re.finditer(rb"(\d+) 0 obj\s*<<(.*?)>>\s*stream\r?\n", pdf, re.S):
        header = m.group(2)
        if b"Length1" in header or b"/Subtype /Form" in header:
            continue
        end = pdf.find(b"endstream", m.end())
        try:
            text = zlib.decompress(pdf[m.end():end]).decode("latin1")
        except zlib.error:
            continue
        if " re W n" in text and (best is None or len(text) > len(best)):
            best = text
    return best


def parse(text):
    """Stroked polylines (colour, points), short segments, and text runs with positions."""
    tokens = re.findall(r"\((?:\\.|[^\\)])*\)|\[[^\]]*\]|/[^\s/\[\]()<>]+|[^\s\[\]()<>/]+", text)
    stack, colour, current = [], None, []
    paths, segments, texts, pos = [], [], [], [0.0, 0.0]
    for t in tokens:
        if re.fullmatch(r"-?[\d.]+", t) or t[0] in "([/":
            stack.append(t)
            continue
        if t == "RG":
            colour = tuple(float(v) for v in stack[-3:])
        elif t == "G":
            colour = (float(stack[-1]),) * 3
        elif t == "m":
            current = [(float(stack[-2]), float(stack[-1]))]
        elif t == "l":
            current.append((float(stack[-2]), float(stack[-1])))
        elif t == "S":
            if current:
                paths.append((colour, current))
            current = []
        elif t in ("B", "f", "n"):
            if len(current) == 2:
                segments.append(current)
            current = []
        elif t == "BT":
            pos = [0.0, 0.0]
        elif t == "Td":
            pos = [pos[0] + float(stack[-2]), pos[1] + float(stack[-1])]
        elif t == "Tm":
            pos = [float(stack[-2]), float(stack[-1])]
        elif t in ("Tj", "TJ"):
            s = stack[-1]
            s = "".join(re.findall(r"\(((?:\\.|[^\\)])*)\)", s)) if s[0] == "[" else s[1:-1]
            texts.append((pos[0], pos[1], s))
        stack = []
    return paths, segments, texts


def calibration(texts, segments):
    labels = []  # (x, y, exponent) of each "10^e" label
    for j, (x, y, s) in enumerate(texts):
        if s != "10":
            continue
        e, k = "", j + 1
        while k < len(texts) and texts[k][2] != "10" and len(texts[k][2]) <= 2 and abs(texts[k][1] - y) < 8:
            e += texts[k][2]
            k += 1
        negative = e[:1] in (" ", "\x00", "\\")
        v = int(re.sub(r"[^0-9]", "", e))
        labels.append((x, y, -v if negative else v))
    xs = [l for l in labels if l[1] < 35]
    ys = [l for l in labels if l[1] >= 35 and l[0] < 70]
    vt = sorted({round(s[0][0], 3) for s in segments
                 if abs(s[0][0] - s[1][0]) < 1e-6 and abs(s[0][1] - 43.2) < 1e-3 and abs(s[1][1] - s[0][1]) > 3})
    ht = sorted({round(s[0][1], 3) for s in segments
                 if abs(s[0][1] - s[1][1]) < 1e-6 and abs(s[0][0] - 72) < 1e-3 and abs(s[1][0] - s[0][0]) > 3})

    def axis(labs, ticks, coord, shift):
        pairs = [(min(ticks, key=lambda u: abs(u - l[coord] - shift)), l[2]) for l in labs]
        (p0, v0), (p1, v1) = pairs[0], pairs[-1]
        a = (v1 - v0) / (p1 - p0)
        return lambda p: 10 ** (v0 + a * (p - p0))

    return axis(xs, vt, 0, 11.26), axis(ys, ht, 1, 4.74)


def bands(pdf, label="II"):
    paths, segments, texts = parse(page_stream(pdf))
    fx, fy = calibration(texts, segments)
    legend = {}
    for colour, pts in paths:
        if len(pts) == 2 and abs(pts[0][0] - 89.28) < 0.5 and abs(pts[1][0] - 109.44) < 0.5:
            near = [t for t in texts if abs(t[0] - 125.28) < 1 and abs(t[1] - (pts[0][1] - 5.04)) < 1.5]
            if near:
                legend[colour] = near[0][2]
    out = {}
    for colour, pts in paths:
        if len(pts) < 3 or legend.get(colour) != label:
            continue
        for x, y in pts:
            h = fx(x)
            i = round(-10 * math.log(h))
            if abs(-10 * math.log(h) - i) > 0.05:
                raise ValueError(f"h = {h} is not exp(-i/10)")
            out.setdefault(i, []).append(fy(y))
    return out


def main():
    git_dir, commit = sys.argv[1], sys.argv[2]
    figures = FIGURES_3D if len(sys.argv) < 4 or sys.argv[3] == "3d" else FIGURES_2D
    print("figure,shape,estimator,i,h,lo,hi")
    for fig, shape, est in figures:
        pdf = subprocess.run(["git", "--git-dir", git_dir, "show", f"{commit}:graphs/{fig}.pdf"],
                             check=True, capture_output=True).stdout
        for i, v in sorted(bands(pdf).items()):
            print(f'{fig},"{shape}",{est},{i},{math.exp(-i / 10):.6g},{min(v):.5g},{max(v):.5g}')


if __name__ == "__main__":
    main()
