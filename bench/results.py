#!/usr/bin/python3
"""Rewrites the measured tables of docs/results.md from the files a test run and a study run write.

usage: bench/results.py BUILD_DIR STUDY_DIR RESULTS_MD

docs/results.md is prose around tables; each table sits between `<!-- results:NAME -->` and
`<!-- /results -->` and is replaced by what this script makes from:
  mesa         BUILD_DIR/reference-comparison-{llvmpipe,llvmpipe-interpreted,softpipe}.csv
                                                                        (ctest: test_reference)
  conformance  BUILD_DIR/conformance/SCENE-{llvmpipe,softpipe}.csv      (ctest: test_conformance_*)
  textures     BUILD_DIR/conformance/textures-{llvmpipe,softpipe}.csv   (test_conformance_* "[textures]",
               every case in one process: bench/run-study runs them so)
  large-coordinates
               STUDY_DIR/stability.txt               (the [stability] tests, which bench/run-study runs)
  throughput, frame
               STUDY_DIR/{throughput,figure-1.1-frame}.md (quadshade-bench-throughput)
  scaling      STUDY_DIR/scaling.md                  (quadshade-bench-throughput --scaling)
  interpreter  STUDY_DIR/interpreter.md              (quadshade-bench-throughput --interpreted)
  generated    STUDY_DIR/generated.md                (quadshade-bench-throughput --generated)
  guard        STUDY_DIR/compare-builds.md           (bench/compare-builds, run-study --previous);
               a study run without --previous says so in the block
  error        STUDY_DIR/study.csv              (quadshade study --study bench/study.txt)
  bake, bake-seams, bake-normals, bake-lit
               STUDY_DIR/bake.md, bake-seams.md, bake-normals.md, bake-lit.md
                                                                        (quadshade-bench-bake)
  startup      STUDY_DIR/startup.md                                     (quadshade-bench-startup)
  host         this machine and the date
Every block but `host` ends with the machine and date it was rewritten on, so that a page whose
blocks come from different runs says which is which. A block whose input is missing is left as it
was, and said so on stderr, so a partial run never blanks a table; the prose is written by hand and
says how each table is measured and what it means.
"""
import csv
import datetime
import glob
import os
import platform
import re
import sys
from collections import OrderedDict

SCENES = OrderedDict([
    ("torus-rolled", "double-sided torus under a camera rolled 28° (self-occluding)"),
    ("overlap", "overlapping objects: squares at three depths, a box and a torus crossing one, mixed order"),
    ("overlap-reversed", "the same drawn in reverse order"),
    ("hierarchy", "node hierarchy: matrix, TRS with non-uniform scale, a sheared grandchild"),
    ("grazing-plane", "200x200 plane seen from 0.3 above, crossing the near plane and the screen's sides"),
    ("sliver-fan", "double-sided fan of 240 slivers and a strip of long thin triangles"),
    ("culling", "back faces culled: a torus cut by the near plane, a mirrored box, squares from behind, single-sided slivers"),
])


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def counts(r):
    return f"{r['over_1']} · {r['over_2']} · {r['max_steps']}/255"


def mesa_table(build):
    paths = [os.path.join(build, f"reference-comparison-{d}.csv") for d in ("llvmpipe", "softpipe")]
    if not all(os.path.exists(p) for p in paths):
        return None
    lp = OrderedDict((r["case"], r) for r in read_csv(paths[0]))
    sp = {r["case"]: r for r in read_csv(paths[1])}
    interpreted_path = os.path.join(build, "reference-comparison-llvmpipe-interpreted.csv")
    ip = {r["case"]: r for r in read_csv(interpreted_path)} if os.path.exists(interpreted_path) else {}
    out = ["| case | pixels | vs llvmpipe, `fine`: >1/255 · >2/255 · max · coverage | "
           "its GLSL run by the interpreter vs llvmpipe: >1/255 · >2/255 · max · coverage | "
           "vs softpipe, `coarse-lower` + `right-top` + `separate`: >1/255 · >2/255 · max · coverage |",
           "|---|---|---|---|---|"]
    for case, r in lp.items():
        s = sp.get(case)
        soft = f"{counts(s)} · {s['coverage_mismatch']}" if s else "-"
        i = ip.get(case)
        interpreted = f"{counts(i)} · {i['coverage_mismatch']}" if i else "-"
        out.append(f"| {case} | {r['pixels']} | {counts(r)} · {r['coverage_mismatch']} | {interpreted} | {soft} |")
    return out


def scene_sums(rows):
    """Sums over a scene's shaders, the largest difference, and the shaders over 1/255."""
    over = [r for r in rows if int(r["over_1"]) > 0]
    return {
        "size": f"{rows[0]['width']}x{rows[0]['height']}",
        "covered": sum(int(r["covered"]) for r in rows),
        "over_1": sum(int(r["over_1"]) for r in rows),
        "over_2": sum(int(r["over_2"]) for r in rows),
        "max": max(int(r["max_steps"]) for r in rows),
        "coverage": sum(int(r["coverage_mismatch"]) for r in rows),
        "shaders": len(rows),
        "which": ", ".join(f"{r['shader']} {r['over_1']}" for r in sorted(over, key=lambda r: -int(r["over_1"]))),
    }


def conformance_table(build):
    found = OrderedDict()
    for path in sorted(glob.glob(os.path.join(build, "conformance", "*-llvmpipe.csv"))):
        scene = os.path.basename(path)[:-len("-llvmpipe.csv")]
        soft = os.path.join(build, "conformance", f"{scene}-softpipe.csv")
        if scene.startswith("textures") or not os.path.exists(soft):
            continue
        found[scene] = (read_csv(path), read_csv(soft))
    if not found:
        return None
    order = [s for s in SCENES if s in found] + [s for s in found if s not in SCENES]
    out = ["| scene | llvmpipe size · softpipe size | shaders | covered pixels (llvmpipe) | "
           "vs llvmpipe, `fine`: >1/255 · >2/255 · max · coverage | "
           "vs softpipe, `coarse-lower` + `right-top` + `separate`: >1/255 · >2/255 · max · coverage |",
           "|---|---|---|---|---|---|"]
    for scene in order:
        lp, sp = (scene_sums(rows) for rows in found[scene])
        which = f" ({lp['which']})" if lp["which"] and lp["over_1"] < 1000 else ""
        out.append(f"| {SCENES.get(scene, scene)} | {lp['size']} · {sp['size']} | {lp['shaders']} | {lp['covered']} | "
                   f"{lp['over_1']} · {lp['over_2']} · {lp['max']}/255 · {lp['coverage']}{which} | "
                   f"{sp['over_1']} · {sp['over_2']} · {sp['max']}/255 · {sp['coverage']} |")
    return out


def textures_table(build):
    """Per texture conformance scene: the shaders' sums against each driver, and which differ."""
    paths = [os.path.join(build, "conformance", f"textures-{d}.csv") for d in ("llvmpipe", "softpipe")]
    if not os.path.exists(paths[0]):
        return None
    scenes = OrderedDict()
    for r in read_csv(paths[0]):
        scenes.setdefault(r["scene"], []).append(r)
    soft = OrderedDict()
    if os.path.exists(paths[1]):
        for r in read_csv(paths[1]):
            soft.setdefault(r["scene"], []).append(r)

    def sums(rows):
        return (sum(int(r["over_1"]) for r in rows), sum(int(r["over_2"]) for r in rows),
                max(int(r["max_steps"]) for r in rows), sum(int(r["coverage_mismatch"]) for r in rows))

    out = ["| scene | shaders | covered pixels (each) | vs llvmpipe: >1/255 · >2/255 · max · coverage | "
           "shaders bit-exact against llvmpipe (pixels that are not, per shader) | "
           "vs softpipe: >1/255 · >2/255 · max · coverage |",
           "|---|---|---|---|---|---|"]
    for scene, rows in scenes.items():
        inexact = [f"{r['shader']} {r['not_bit_exact']}" for r in rows if int(r["not_bit_exact"]) > 0]
        exact = f"{len(rows) - len(inexact)} of {len(rows)}" + (f" ({', '.join(inexact)})" if inexact else "")
        sp = soft.get(scene)
        soft_cell = "{} · {} · {}/255 · {}".format(*sums(sp)) if sp else "-"
        out.append(f"| {scene} | {len(rows)} | {rows[0]['covered']} | "
                   "{} · {} · {}/255 · {}".format(*sums(rows)) + f" | {exact} | {soft_cell} |")
    return out


def large_coordinates_table(study):
    """The table tests/shading/test_large_coordinates.cpp prints: per noise, the largest |float - double|
    at each offset, plain and wrapped by the noise's period."""
    path = os.path.join(study, "stability.txt")
    if not os.path.exists(path):
        return None
    with open(path) as f:
        lines = f.read().splitlines()
    try:
        start = next(i for i, l in enumerate(lines) if l.startswith("large coordinates:"))
    except StopIteration:
        return None
    offsets = lines[start + 1].split()[1:]
    out = ["| noise | " + " | ".join(offsets) + " |", "|---|" + "---|" * len(offsets)]
    name = None
    for line in lines[start + 2:]:
        label, values = line[:16].strip(), line[16:].split()
        if line[16:].strip().startswith("float vs double"):
            continue
        if len(values) != len(offsets):
            break
        if label == "wrapped" and name:
            out.append(f"| {name}, wrapped | " + " | ".join(values) + " |")
        else:
            name = label
            out.append(f"| {name} | " + " | ".join(values) + " |")
    return out if len(out) > 2 else None


def markdown_file(study, name):
    path = os.path.join(study, name)
    if not os.path.exists(path):
        return None
    with open(path) as f:
        return [l.rstrip() for l in f if l.strip().startswith("|")]


def table_and_notes(study, name):
    """A table with the lines after it that say how it was measured (runs, load)."""
    path = os.path.join(study, name)
    if not os.path.exists(path):
        return None
    with open(path) as f:
        return [l.rstrip() for l in f.read().strip().splitlines()]


def pareto_front(rows):
    front = []
    for r in sorted(rows, key=lambda r: (r["ms"], r["rms_vs_truth"])):
        if not front or r["rms_vs_truth"] < 0.99 * front[-1]["rms_vs_truth"]:
            front.append(r)
    return front


def error_table(study):
    path = os.path.join(study, "study.csv")
    if not os.path.exists(path):
        return None
    rows = read_csv(path)
    for r in rows:
        r["ms"], r["rms_vs_truth"] = float(r["ms"]), float(r["rms_vs_truth"])
    cases = OrderedDict()
    for r in rows:
        cases.setdefault(f"{r['shader']} {r['view']}", []).append(r)
    modes = list(OrderedDict.fromkeys(r["mode"] for r in rows))
    out = ["| case | " + " | ".join(modes) + " | Pareto front |", "|---|" + "---|" * (len(modes) + 1)]
    for case, rs in cases.items():
        by_mode = {r["mode"]: r for r in rs}
        cells = [f"{by_mode[m]['rms_vs_truth']:.3f} · {by_mode[m]['ms']:.2f}" if m in by_mode else "-" for m in modes]
        front = ", ".join(r["mode"] for r in pareto_front(rs))
        out.append(f"| {case} | " + " | ".join(cells) + f" | {front} |")
    return out


def host_line():
    model = "unknown CPU"
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    model = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    flags = ""
    try:
        with open("/proc/cpuinfo") as f:
            text = f.read()
        flags = "AVX-512" if "avx512f" in text else "AVX2" if "avx2" in text else "no AVX2"
    except OSError:
        pass
    return [f"Measured on {model} ({os.cpu_count()} cores, {flags}), {platform.system()} "
            f"{platform.release()}, {datetime.date.today().isoformat()}."]


def measured_line():
    """The line that ends every generated table: where and when it was rewritten."""
    return "_" + host_line()[0] + "_"


def guard_table(study):
    """The previous build against this one, or a line saying this run had no previous build."""
    table = markdown_file(study, "compare-builds.md")
    if table:
        return table
    if os.path.exists(os.path.join(study, "throughput.md")):
        return ["_This run had no previous build to compare with: `bench/run-study --previous OLD_BUILD DIR`._"]
    return None


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    build, study, doc = sys.argv[1:]
    makers = {
        "host": host_line,
        "mesa": lambda: mesa_table(build),
        "conformance": lambda: conformance_table(build),
        "textures": lambda: textures_table(build),
        "large-coordinates": lambda: large_coordinates_table(study),
        "throughput": lambda: markdown_file(study, "throughput.md"),
        "frame": lambda: markdown_file(study, "figure-1.1-frame.md"),
        "scaling": lambda: markdown_file(study, "scaling.md"),
        "interpreter": lambda: markdown_file(study, "interpreter.md"),
        "generated": lambda: markdown_file(study, "generated.md"),
        "guard": lambda: guard_table(study),
        "error": lambda: error_table(study),
        "bake": lambda: markdown_file(study, "bake.md"),
        "bake-seams": lambda: markdown_file(study, "bake-seams.md"),
        "bake-normals": lambda: markdown_file(study, "bake-normals.md"),
        "bake-lit": lambda: markdown_file(study, "bake-lit.md"),
        "startup": lambda: table_and_notes(study, "startup.md"),
    }
    with open(doc) as f:
        text = f.read()
    block = re.compile(r"(<!-- results:(\w[\w-]*) -->\n)(.*?)(<!-- /results -->)", re.S)

    def replace(m):
        name = m.group(2)
        if name not in makers:
            sys.exit(f"results.py: {doc}: unknown block '{name}'")
        lines = makers[name]()
        if not lines:
            print(f"results.py: {name}: no input in this run, kept as it was", file=sys.stderr)
            return m.group(0)
        if name != "host":
            lines = lines + ["", measured_line()]
        return m.group(1) + "\n".join(lines) + "\n" + m.group(4)

    new, n = block.subn(replace, text)
    tmp = doc + ".tmp"
    with open(tmp, "w") as f:
        f.write(new)
    os.replace(tmp, doc)
    print(f"results.py: {n} blocks in {doc}", file=sys.stderr)


if __name__ == "__main__":
    main()
