#!/usr/bin/env python3
"""Topology grid of issue 15 (called by bench/topology.sh; see there for the options).

Every cell: an analytic surface (sphere, torus, double and triple torus) sampled by
`bench_points surface` at a size, a density (uniform / graded), a noise level (σ in % of the
bounding-box diagonal) and with exact normals or none (estimated by hrsr), reconstructed by
`hrsr reconstruct` at its defaults (HRsR at p = 0.5, 0.25, 0.125 and RsR). A cell is exact when
the output is one closed, manifold piece of the surface's genus. CGAL's Advancing Front runs on
the same clouds for reference when it was built. Runs cells side by side (one thread each), so
the times are single-thread times.
"""
import argparse
import concurrent.futures
import json
import os
import subprocess
import sys
import time

GENUS = {"sphere": 0, "torus": 1, "double_torus": 2, "triple_torus": 3}
METHODS = [("hrsr p=0.5", ["--collapse-ratio", "0.5"]),
           ("hrsr p=0.25", ["--collapse-ratio", "0.25"]),
           ("hrsr p=0.125", []),  # the default
           ("rsr", ["--method", "rsr"])]


def run(cmd, timeout):
    start = time.monotonic()
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                       timeout=timeout)
    return p, time.monotonic() - start


def cloud_path(work, cell):
    shape, n, density, noise, normals = cell
    return os.path.join(work, f"{shape}_{n}_{density}_{noise}_{normals}.ply")


def make_cloud(build, work, cell):
    path = cloud_path(work, cell)
    if not os.path.exists(path):
        shape, n, density, noise, normals = cell
        tmp = path + ".tmp.ply"
        subprocess.run([os.path.join(build, "bench", "bench_points"), "surface", shape, str(n),
                        density, str(noise), normals, tmp], check=True)
        os.replace(tmp, path)
    return path


def measure_hrsr(hrsr, work, cell, method, args, timeout):
    cloud = cloud_path(work, cell)
    stem = os.path.splitext(cloud)[0] + "_" + method.replace(" ", "_").replace("=", "")
    mesh, report = stem + ".mesh.ply", stem + ".json"
    cmd = [hrsr, "reconstruct", cloud, "-o", mesh, "--report",
           report, "--threads", "1"] + args
    try:
        p, seconds = run(cmd, timeout)
    except subprocess.TimeoutExpired:
        return {"error": "timeout"}
    if p.returncode != 0:
        return {"error": (p.stderr.strip().splitlines() or ["exit %d" % p.returncode])[-1]}
    r = json.load(open(report))
    os.remove(mesh)
    m = r["mesh"]
    return {"genus": m["largest_component"]["genus"], "boundary_edges": m["boundary_edges"],
            "components": m["components"], "non_manifold": m["non_manifold_edges"] +
            m["non_manifold_vertices"], "r_v": r["points"]["vertex_reference_ratio"],
            "handles": r["rsr"]["handles"], "hop_limits": sorted(set(r["rsr"].get("handle_hop_limits", []))),
            "seconds": seconds}


def measure_cgal(build, work, cell, timeout):
    exe = os.path.join(build, "bench", "cgal_advancing_front")
    if not os.path.exists(exe):
        return None
    cloud = cloud_path(work, cell)
    mesh = os.path.splitext(cloud)[0] + "_cgal.mesh.ply"
    try:
        p, seconds = run([exe, cloud, mesh], timeout)
    except subprocess.TimeoutExpired:
        return {"error": "timeout"}
    if p.returncode != 0:
        return {"error": (p.stderr.strip().splitlines() or ["exit %d" % p.returncode])[-1]}
    c = subprocess.run([os.path.join(build, "apps", "hrsr"), "check", mesh, "--json",
                        "--no-self-intersections"], stdout=subprocess.PIPE, text=True, check=True)
    os.remove(mesh)
    m = json.loads(c.stdout)
    return {"genus": m["largest_component"]["genus"], "boundary_edges": m["boundary_edges"],
            "components": m["components"], "non_manifold": m["non_manifold_edges"] +
            m["non_manifold_vertices"], "seconds": seconds}


def exact(result, genus):
    return ("error" not in result and result["genus"] == genus and result["boundary_edges"] == 0
            and result["components"] == 1 and result["non_manifold"] == 0)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--shapes", default="sphere,torus,double_torus,triple_torus")
    ap.add_argument("--sizes", default="5000,20000,100000")
    ap.add_argument("--densities", default="uniform,graded")
    ap.add_argument("--noise", default="0,0.1,0.3")
    ap.add_argument("--normals", default="normals,none")
    ap.add_argument("--methods", default=",".join(m for m, _ in METHODS))
    ap.add_argument("--no-cgal", action="store_true")
    ap.add_argument("--hrsr", help="the hrsr binary to measure (default: BUILD/apps/hrsr; an "
                    "older build for a before/after table)")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--timeout", type=float, default=1800)
    a = ap.parse_args()
    hrsr = a.hrsr or os.path.join(a.build, "apps", "hrsr")
    work = os.path.join(a.out, "clouds")
    os.makedirs(work, exist_ok=True)
    cells = [(s, int(n), d, z, nm) for s in a.shapes.split(",") for n in a.sizes.split(",")
             for d in a.densities.split(",") for z in a.noise.split(",")
             for nm in a.normals.split(",")]
    methods = [(m, args) for m, args in METHODS if m in a.methods.split(",")]
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
        list(pool.map(lambda c: make_cloud(a.build, work, c), cells))
        jobs = {}
        for c in cells:
            for m, args in methods:
                jobs[(c, m)] = pool.submit(measure_hrsr, hrsr, work, c, m, args, a.timeout)
            if not a.no_cgal:
                jobs[(c, "cgal")] = pool.submit(measure_cgal, a.build, work, c, a.timeout)
        results = []
        for (c, m), f in jobs.items():
            r = f.result()
            if r is None:
                continue
            shape, n, density, noise, normals = c
            row = {"shape": shape, "points": n, "density": density, "noise_percent": float(noise),
                   "normals": normals == "normals", "method": m, "expected_genus": GENUS[shape]}
            row.update(r)
            row["exact"] = exact(r, GENUS[shape])
            results.append(row)
            print(format_row(row), flush=True)
    json.dump(results, open(os.path.join(a.out, "topology.json"), "w"), indent=1)
    with open(os.path.join(a.out, "topology.md"), "w") as md:
        md.write(markdown(results))
    ours = [r for r in results if r["method"] != "cgal"]
    print(f"exact and closed: {sum(r['exact'] for r in ours)} of {len(ours)} cells (ours); "
          f"tables in {os.path.join(a.out, 'topology.md')}")


def format_row(r):
    what = (f"{r['shape']:12s} {r['points']:>7d} {r['density']:7s} noise {r['noise_percent']:.1f}% "
            f"{'normals' if r['normals'] else 'no normals':10s} {r['method']:12s}")
    if "error" in r:
        return what + " error: " + r["error"]
    return (what + f" genus {r['genus']} (want {r['expected_genus']}) boundary {r['boundary_edges']}"
            f" components {r['components']} {r['seconds']:.1f} s" + ("" if r["exact"] else "  <-"))


def cell_text(r):
    if r is None:
        return ""
    if "error" in r:
        return "error"
    mark = "✓" if r["exact"] else f"g{r['genus']} b{r['boundary_edges']}" + (
        f" c{r['components']}" if r["components"] != 1 else "")
    return mark


def markdown(results):
    """One table per (noise, normals): rows shape × size × density, columns the methods."""
    methods = []
    for r in results:
        if r["method"] not in methods:
            methods.append(r["method"])
    index = {(r["shape"], r["points"], r["density"], r["noise_percent"], r["normals"], r["method"]): r
             for r in results}
    out = ["✓ = one closed manifold piece of the right genus; otherwise g = genus of the largest "
           "piece (holes counted as boundary loops), b = boundary edges, c = pieces.\n"]
    groups = sorted({(r["noise_percent"], r["normals"]) for r in results},
                    key=lambda g: (g[0], not g[1]))
    rows = []
    for r in results:
        key = (r["shape"], r["points"], r["density"])
        if key not in rows:
            rows.append(key)
    for noise, normals in groups:
        out.append(f"\n**noise σ = {noise:g} % of the diagonal, "
                   f"{'exact normals' if normals else 'normals estimated'}**\n")
        out.append("| surface | points | density | " + " | ".join(methods) + " |")
        out.append("|---|---:|---|" + "---|" * len(methods))
        for shape, n, density in rows:
            cells = [cell_text(index.get((shape, n, density, noise, normals, m))) for m in methods]
            out.append(f"| {shape} | {n} | {density} | " + " | ".join(cells) + " |")
    ours = [r for r in results if r["method"] != "cgal"]
    total = f"\nExact: {sum(r['exact'] for r in ours)} of {len(ours)} cells of ours"
    cgal = [r for r in results if r["method"] == "cgal"]
    if cgal:
        total += f"; CGAL Advancing Front {sum(r['exact'] for r in cgal)} of {len(cgal)}"
    out.append(total + ".")
    return "\n".join(out) + "\n"


if __name__ == "__main__":
    sys.exit(main())
