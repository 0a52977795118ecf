#!/usr/bin/python3
"""Tables and plots from bench/compare.py's results.json (Debian python3-matplotlib).

usage: bench_report.py RESULTS.json MARKDOWN PLOT_DIR

Writes the PNG plots into PLOT_DIR and the generated section into MARKDOWN: if MARKDOWN exists
and has the markers below, only the text between them is replaced (the rest of the document is
kept as it is); otherwise MARKDOWN is written with just the section.
"""
import json
import os
import sys
from pathlib import Path

BEGIN = "<!-- BEGIN bench/compare.sh (generated: edits between these markers are overwritten) -->"
END = "<!-- END bench/compare.sh -->"

METHOD_ORDER = ["hrsr_p0.5", "hrsr_p0.25", "hrsr_p0.125", "rsr", "meshlab_bpa",
                "meshlab_poisson", "cgal_afront", "open3d_bpa", "open3d_poisson"]


def fmt(value, digits=1):
    if value is None:
        return "–"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, int):
        return f"{value:,}"
    return f"{value:,.{digits}f}"


def sci(value):
    return "–" if value is None else f"{value:.2e}"


def genus_text(check):
    genus = check.get("genus_of_closed_components", [])
    if not genus:
        return "–"
    if len(genus) > 4:
        return f"{len(genus)} closed"
    return ", ".join(str(g) for g in genus)


def stamp(run, meta):
    return run.get("measured", {"date": meta["date"], "commit": meta["commit"]})


def method_cell(run, meta):
    """The method's label, with the date of the run it came from when that is not this run's."""
    date = stamp(run, meta)["date"]
    return run["method_label"] + ("" if date == meta["date"] else f" ({date})")


def table(runs, meta):
    head = ("| method | status | time (s) | peak RSS (MB) | V | F | r_v | boundary edges | loops "
            "| non-manifold e / v | components | genus (closed) | self-int. pairs "
            "| degenerate / duplicate | min angle < 10° | Chamfer | Hausdorff |")
    rows = [head, "|" + "---|" * 2 + "---:|" * 15]
    for r in runs:
        c = r.get("check", {})
        ref = c.get("reference", {})
        rv = c.get("input", {}).get("vertex_reference_ratio")
        angle = c.get("min_angle_degrees", {})
        below = None
        if angle.get("faces"):
            below = 100.0 * angle["below_10"] / angle["faces"]
        rows.append("| " + " | ".join([
            method_cell(r, meta), r["status"], fmt(r["seconds"]), fmt(r["peak_rss_mb"], 0),
            fmt(c.get("vertices")), fmt(c.get("faces")),
            "–" if rv is None else f"{100 * rv:.3f} %",
            fmt(c.get("boundary_edges")), fmt(c.get("boundary_loops")),
            f"{fmt(c.get('non_manifold_edges'))} / {fmt(c.get('non_manifold_vertices'))}"
            if c else "–",
            fmt(c.get("components")), genus_text(c) if c else "–",
            fmt(c.get("self_intersecting_pairs")),
            f"{fmt(c.get('degenerate_faces'))} / {fmt(c.get('duplicate_faces'))}" if c else "–",
            "–" if below is None else f"{below:.1f} %",
            sci(ref.get("chamfer_of_diagonal")), sci(ref.get("hausdorff_of_diagonal")),
        ]) + " |")
    return "\n".join(rows)


DATASET_ORDER = ["bunny", "dragon", "lion", "kitten", "owl"]


def dataset_names(runs):
    """Data sets in report order (whatever order a resumed run appended them in): the scans and
    meshes first, then the scaling series by size."""
    first = {}
    for r in runs:
        first.setdefault(r["dataset"], r)
    return sorted(first, key=lambda d: (
        first[d].get("series") is not None, first[d].get("points", 0)
        if first[d].get("series") else DATASET_ORDER.index(d) if d in DATASET_ORDER else 99, d))


def ordered(runs):
    return sorted(runs, key=lambda r: METHOD_ORDER.index(r["method"])
                  if r["method"] in METHOD_ORDER else 99)


def save(plt, fig, ax, path, legend_outside=False):
    ax.grid(True, which="major", alpha=0.3)
    if legend_outside:  # bar charts: a legend inside would cover the last group's bars
        ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    else:
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plots(runs, plot_dir):
    """Returns [(file name, caption)] of the plots written."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    plot_dir.mkdir(parents=True, exist_ok=True)
    made = []
    labels = {r["method"]: r["method_label"] for r in runs}
    methods = [m for m in METHOD_ORDER if m in labels]
    series = [r for r in runs if r.get("series") == "dragon" and r["status"] == "ok"]
    if series:
        for key, ylabel, name in (("seconds", "wall time (s)", "scaling_time.png"),
                                  ("peak_rss_mb", "peak RSS (MB)", "scaling_memory.png")):
            fig, ax = plt.subplots(figsize=(7, 4.5))
            for m in methods:
                pts = sorted((r["points"], r[key]) for r in series
                             if r["method"] == m and r[key] is not None)
                if pts:
                    ax.plot([p[0] for p in pts], [p[1] for p in pts], marker="o", label=labels[m])
            ax.set_xscale("log")
            ax.set_yscale("log")
            sizes = sorted({r["points"] for r in series})
            ax.set_xticks(sizes)
            ax.set_xticklabels([f"{n / 1e6:g}M" if n >= 1e6 else f"{n // 1000}k" for n in sizes])
            ax.minorticks_off()
            ax.set_xlabel("points (dragon surface samples)")
            ax.set_ylabel(ylabel)
            save(plt, fig, ax, plot_dir / name)
            made.append((name, f"{ylabel} against the number of points, dragon series "
                               "(log-log; failed or timed-out runs are missing)"))
    quality = [r for r in runs if r["status"] == "ok" and r.get("series") is None]
    datasets = dataset_names(quality)
    if quality:
        for key, ylabel, name, log in (
                ("r_v", "r_v (% of input points that are vertices)", "rv_per_method.png", False),
                ("boundary_edges", "boundary edges |E_b| (+1, log)", "boundary_per_method.png",
                 True)):
            fig, ax = plt.subplots(figsize=(9.5, 4.5))
            width = 0.8 / max(1, len(methods))
            for i, m in enumerate(methods):
                xs, ys = [], []
                for d, ds in enumerate(datasets):
                    for r in quality:
                        if r["dataset"] == ds and r["method"] == m:
                            c = r["check"]
                            y = (100 * c.get("input", {}).get("vertex_reference_ratio", 0)
                                 if key == "r_v" else c["boundary_edges"] + 1)
                            xs.append(d + (i - (len(methods) - 1) / 2) * width)
                            ys.append(y)
                if xs:
                    ax.bar(xs, ys, width, label=labels[m])
            ax.set_xticks(range(len(datasets)))
            ax.set_xticklabels(datasets)
            if log:
                ax.set_yscale("log")
            ax.set_ylabel(ylabel)
            save(plt, fig, ax, plot_dir / name, legend_outside=True)
            made.append((name, f"{ylabel} per method and data set"))
    return made


def section(results, plot_files, plot_link_dir):
    meta = results["meta"]
    runs = results["runs"]
    out = [BEGIN, "", f"## Comparison ({meta['mode']} run of `bench/compare.sh`)", "",
           f"Measured on {meta['date']} at commit `{meta['commit']}`: {meta['cores']} cores "
           f"({meta['cpu']}), {meta['memory_gb']} GB, {meta['os']}, {meta['compiler']}; "
           f"MeshLab {meta['meshlab']}, CGAL {meta['cgal']}, Open3D {meta['open3d']}. "
           "One run per method and data set, one after the other. Time and peak RSS from "
           "`/usr/bin/time -v` around the reconstructing process (reading and writing "
           "included; for MeshLab `meshlabserver` without the X server, for Open3D the Python "
           "process). Quality from `hrsr check`: r_v = input points that are mesh vertices "
           "(within 1e-6 of the diagonal); Chamfer and Hausdorff relative to the reference's "
           f"bounding-box diagonal ({meta['check_samples']:,} area samples per surface plus "
           f"the vertices). Runs over {meta['timeout_s']:.0f} s are stopped (\"timeout\").", ""]
    earlier = sorted({(stamp(r, meta)["date"], stamp(r, meta)["commit"]) for r in runs
                      if stamp(r, meta)["date"] != meta["date"]})
    if earlier:
        out += ["Rows whose method carries a date are from an earlier run kept by `--resume` ("
                + "; ".join(f"{d} at commit `{c}`" for d, c in earlier)
                + "); compare their times only with rows of the same date.", ""]
    for ds in dataset_names(runs):
        mine = ordered([r for r in runs if r["dataset"] == ds])
        out += [f"### {mine[0]['label']}", "", table(mine, meta), ""]
    for name, caption in plot_files:
        out += [f"![{caption}]({plot_link_dir}/{name})", "", f"*{caption}.*", ""]
    out.append(END)
    return "\n".join(out)


def main(argv):
    if len(argv) != 4:
        print(__doc__.splitlines()[2], file=sys.stderr)
        return 2
    results = json.loads(Path(argv[1]).read_text())
    markdown, plot_dir = Path(argv[2]), Path(argv[3])
    made = plots(results["runs"], plot_dir)
    link = os.path.relpath(plot_dir, markdown.parent)
    text = section(results, made, link)
    if markdown.exists():
        old = markdown.read_text()
        if BEGIN in old and END in old:
            text = old[:old.index(BEGIN)] + text + old[old.index(END) + len(END):]
        else:
            text = old.rstrip("\n") + "\n\n" + text + "\n"
    else:
        text = "# Benchmarks\n\n" + text + "\n"
    tmp = markdown.with_suffix(".tmp")
    tmp.write_text(text)
    tmp.replace(markdown)
    print(f"bench_report: {markdown}, {len(made)} plots in {plot_dir}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
