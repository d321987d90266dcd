#!/usr/bin/python3
"""The benchmarks' page of a bench/run-study folder: DIR/bench.html, with the throughput tables
(quadshade-bench-throughput), the comparison with a previous build, the stability tests' lines and
the undefined-case masks, and a link to the error study's own report (quadshade study's
DIR/report.html).

usage: bench/report.py DIR
"""
import html
import os
import sys


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
    out = ["<!DOCTYPE html><html><head><meta charset='utf-8'><title>quadshade benchmarks</title><style>",
           "body{font-family:sans-serif;margin:1.5em;max-width:1400px}table{border-collapse:collapse;font-size:13px}",
           "td,th{border:1px solid #ccc;padding:2px 6px;text-align:right}th{background:#eee}</style></head><body>",
           "<h1>quadshade: benchmarks and stability</h1>",
           "<p>Error against run time, per shader, view and mode: <a href='report.html'>the study's report</a> "
           "(<code>quadshade study --study bench/study.txt</code>).</p>",
           "<p id='image-check'>images: not checked</p>"]
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
    with open(os.path.join(root, "bench.html"), "w") as f:
        f.write("\n".join(out))
    print(f"report.py: {os.path.join(root, 'bench.html')}")


if __name__ == "__main__":
    main()
