#!/usr/bin/python3
"""Turns quadshade-bench-error's study.csv into plots and an HTML report.

usage: bench/report.py DIR

Reads DIR/study.csv and DIR/views.csv, writes DIR/plots/CASE.png (error against the ground truth
versus time per frame, log-log, one point per mode, the Pareto front drawn) and DIR/report.html
(per case: the plot, the numbers, and each mode's image next to llvmpipe's, the ground truth and a
heat map of its error). Uses Debian's python3-matplotlib.
"""
import csv
import html
import os
import sys
from collections import OrderedDict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

GROUP_MARKERS = {"derivatives": "o", "anti-aliasing": "s", "precision": "^"}


def pareto_front(rows):
    """Modes no other mode beats on both time and error (lower is better for both); an error
    within 1% of a faster mode's is no improvement."""
    front = []
    for r in sorted(rows, key=lambda r: (r["ms"], r["rms_vs_truth"])):
        if not front or r["rms_vs_truth"] < 0.99 * front[-1]["rms_vs_truth"]:
            front.append(r)
    return front


def plot(case, rows, path):
    fig, ax = plt.subplots(figsize=(7.5, 4.8), dpi=100)
    front = pareto_front(rows)
    names = {r["mode"] for r in front}
    for r in rows:
        on_front = r["mode"] in names
        ax.scatter(r["ms"], max(r["rms_vs_truth"], 1e-6), marker=GROUP_MARKERS.get(r["group"], "o"),
                   s=60 if on_front else 30, facecolors="tab:red" if on_front else "none",
                   edgecolors="tab:red" if on_front else "tab:blue")
        ax.annotate(r["mode"], (r["ms"], max(r["rms_vs_truth"], 1e-6)), textcoords="offset points", xytext=(4, 3),
                    fontsize=7)
    ax.plot([r["ms"] for r in front], [max(r["rms_vs_truth"], 1e-6) for r in front], color="tab:red", lw=1,
            label="Pareto front")
    for group, marker in GROUP_MARKERS.items():
        ax.scatter([], [], marker=marker, facecolors="none", edgecolors="k", label=group)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("time per frame (ms, median)")
    ax.set_ylabel("RMS error against the ground truth")
    ax.set_title(case)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def markdown_table(text):
    """The pipe tables quadshade-bench-throughput writes, as HTML."""
    lines = [l.strip() for l in text.splitlines() if l.strip().startswith("|")]
    cells = [[html.escape(c.strip()) for c in l.strip("|").split("|")] for l in lines if not set(l) <= set("|-: ")]
    if not cells:
        return ""
    head = "".join(f"<th>{c}</th>" for c in cells[0])
    body = "".join("<tr>" + "".join(f"<td>{c}</td>" for c in row) + "</tr>" for row in cells[1:])
    return f"<table><tr>{head}</tr>{body}</table>"


def throughput_sections(root):
    """The throughput benchmark's tables, when run-study ran it into the same folder."""
    parts = []
    for name, title, text in (
            ("throughput.md", "Throughput against OSMesa llvmpipe (Table 1.1 plane)",
             "Same run, same cores, in passes (--rounds) that each measure every row in turn: the median over the "
             "passes of each pass's median Mfragments/s, with their min-max; llvmpipe at each vector width in its own "
             "process; speedups taken within each pass against its faster width, target 2x."),
            ("specialisation.md", "Leaving out what a shader does not need",
             "ms per frame with the specialised pipeline against the general path (quads with helper "
             "lanes and a depth buffer for every shader), median over the passes with their min-max."),
            ("figure-1.1-frame.md", "Figure 1.1: rasterizer, ray caster and llvmpipe",
             "One frame at 1264x400, median over the passes of each pass's median frame, with their min-max; "
             "ratios taken within each pass; the BVH is built once per scene."),
            ("scaling.md", "Thread scaling on the noise rows",
             "quadshade alone at 1, 2 and 8 threads: median over the passes of each pass's median frame time "
             "(min-max over the passes); speedups within each pass against one thread."),
            ("compare-builds.md", "This build against the previous one",
             "bench/compare-builds, quadshade-bench-core of both builds run in turn; a ratio below 1 is faster "
             "than the previous build.")):
        path = os.path.join(root, name)
        if os.path.exists(path):
            with open(path) as f:
                parts.append(f"<h2>{title}</h2><p>{text}</p>{markdown_table(f.read())}")
    return parts


def stability_section(root):
    """The lines the [stability] tests print (large coordinates, float environment, silhouettes,
    stiff geometry, long animations), with their pass/fail summary."""
    path = os.path.join(root, "stability.txt")
    if not os.path.exists(path):
        return []
    with open(path) as f:
        lines = [l.rstrip() for l in f if l.strip() and not l.startswith(("Filters:", "~", "="))]
    parts = ["<h2>Numerical stability</h2><p>Printed by the tests tagged [stability] in this run; each "
             "also asserts the documented behaviour (see docs/results.md).</p><pre>",
             html.escape("\n".join(lines)), "</pre>"]
    masks = [s for s in ("float_env_probe", "bricks_aa")
             if os.path.exists(os.path.join(root, f"undefined-{s}-mask.png"))]
    if masks:
        parts.append("<h3>Undefined-case masks</h3><p><code>quadshade render --undefined-mask</code>, "
                     "render and mask side by side: red NaN produced, green division by zero, blue a "
                     "built-in outside its domain (smoothstep e0 &ge; e1, sqrt, log, pow, inversesqrt, "
                     "clamp, atan).</p>")
        for s in masks:
            parts.append(f"<p>{s}: <img src='undefined-{s}.png' width=256> "
                         f"<img src='undefined-{s}-mask.png' width=256 style='image-rendering: pixelated'></p>")
    return parts


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    root = sys.argv[1]
    with open(os.path.join(root, "study.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    with open(os.path.join(root, "views.csv"), newline="") as f:
        views = {(r["shader"], r["view"]): r["description"] for r in csv.DictReader(f)}
    for r in rows:
        for k in ("ms", "rms_vs_llvmpipe", "max_vs_llvmpipe", "rms_vs_truth", "max_vs_truth"):
            r[k] = float(r[k])
    cases = OrderedDict()
    for r in rows:
        cases.setdefault((r["shader"], r["view"]), []).append(r)
    os.makedirs(os.path.join(root, "plots"), exist_ok=True)

    out = ["<!DOCTYPE html><html><head><meta charset='utf-8'><title>quadshade error study</title><style>",
           "body{font-family:sans-serif;margin:1.5em;max-width:1400px}table{border-collapse:collapse;font-size:13px}",
           "td,th{border:1px solid #ccc;padding:2px 6px;text-align:right}th{background:#eee}td.l{text-align:left}",
           "tr.front td{background:#fde8e8}img.px{image-rendering:pixelated;width:256px}figure{display:inline-block;margin:2px}",
           "figcaption{font-size:11px;text-align:center}</style></head><body>",
           "<h1>quadshade: error against run time</h1>",
           "<p>Every derivative, anti-aliasing and precision mode on the anti-aliased shaders and views that "
           "stress them. Errors are over RGB in [0, 1]: against OSMesa llvmpipe rendering the same GLSL "
           "(supersampled modes: llvmpipe supersampled alike), and against the ground truth, the "
           "un-anti-aliased pattern box-filtered over each pixel by dense supersampling in double precision. "
           "<code>step</code> is supersampling 1x1. Rows on the Pareto front (nothing is both faster and more "
           "accurate) are shaded. Heat maps show |mode - truth|, full scale 0.25.</p>",
           "<p id='image-check'>images: not checked</p><ul>"]
    for (shader, view) in cases:
        out.append(f"<li><a href='#{shader}-{view}'>{shader}, {view}</a></li>")
    out.append("</ul>")
    for (shader, view), rs in cases.items():
        case = f"{shader}-{view}"
        plot(f"{shader}, {view}", rs, os.path.join(root, "plots", case + ".png"))
        front = {r["mode"] for r in pareto_front(rs)}
        out.append(f"<h2 id='{case}'>{html.escape(shader)}, {html.escape(view)}</h2>")
        out.append(f"<p>{html.escape(views.get((shader, view), ''))}; {rs[0]['width']}x{rs[0]['height']} pixels.</p>")
        out.append(f"<img src='plots/{case}.png' alt='error against time, {case}'>")
        out.append("<table><tr><th>mode</th><th>group</th><th>shader</th><th>ms</th><th>RMS vs llvmpipe</th>"
                   "<th>max vs llvmpipe</th><th>RMS vs truth</th><th>max vs truth</th></tr>")
        for r in rs:
            cls = " class='front'" if r["mode"] in front else ""
            out.append(f"<tr{cls}><td class='l'>{r['mode']}</td><td class='l'>{r['group']}</td>"
                       f"<td class='l'>{r['variant']}</td><td>{r['ms']:.3f}</td><td>{r['rms_vs_llvmpipe']:.2e}</td>"
                       f"<td>{r['max_vs_llvmpipe']:.3f}</td><td>{r['rms_vs_truth']:.2e}</td>"
                       f"<td>{r['max_vs_truth']:.3f}</td></tr>")
        out.append("</table>")
        for r in rs:
            out.append(f"<div><b>{r['mode']}</b><br>")
            for src, cap in ((r["image"], "quadshade"), (r["llvmpipe_image"], "OSMesa llvmpipe"),
                             (r["truth_image"], "ground truth"), (r["heat_image"], "|quadshade - truth|")):
                out.append(f"<figure><img class='px' src='{src}' alt='{cap}'><figcaption>{cap}</figcaption></figure>")
            out.append("</div>")
    out.extend(throughput_sections(root))
    out.extend(stability_section(root))
    # Tells a headless browser (and a reader) whether every image loaded.
    out.append("""<script>
window.addEventListener('load', () => {
  const images = Array.from(document.images);
  const ok = images.filter(i => i.complete && i.naturalWidth > 0).length;
  document.getElementById('image-check').textContent = `images: ${ok}/${images.length} loaded`;
});
</script></body></html>""")
    with open(os.path.join(root, "report.html"), "w") as f:
        f.write("\n".join(out))
    print(f"report.py: {len(cases)} cases, {len(rows)} modes -> {os.path.join(root, 'report.html')}")


if __name__ == "__main__":
    main()
