#!/usr/bin/python3
"""Runs the reconstruction comparison of bench/compare.sh (use that script: it installs the
benchmark packages and builds first).

Every (data set, method) pair runs once under /usr/bin/time -v (wall time, peak RSS of the
reconstructing process), then `hrsr check` measures the mesh (against the input cloud, and
against a reference surface where the data has one). Results go to OUT/results.json after each
run (--resume skips runs already there); bench_report.py turns them into tables and plots.
"""
import argparse
import json
import os
import platform
import shutil
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
BENCH = ROOT / "bench"
PYTHON = "/usr/bin/python3"  # Debian's, with python3-open3d / python3-matplotlib

# Dragon scaling series (points sampled on the dragon_vrip surface, normals of the triangles).
SCALING_FULL = [50_000, 100_000, 200_000, 400_000, 800_000, 1_600_000]
SCALING_QUICK = [10_000, 20_000]

METHODS = {
    "hrsr_p0.5": "HRsR p = 0.5",
    "hrsr_p0.25": "HRsR p = 0.25",
    "hrsr_p0.125": "HRsR p = 0.125",
    "rsr": "RsR",
    "meshlab_bpa": "MeshLab Ball Pivoting",
    "meshlab_poisson": "MeshLab Screened Poisson",
    "cgal_afront": "CGAL Advancing Front",
    "open3d_bpa": "Open3D Ball Pivoting",
    "open3d_poisson": "Open3D Poisson",
}


class Dataset:
    def __init__(self, name, label, cloud, points, normals, reference=None, series=None):
        self.name, self.label, self.cloud = name, label, Path(cloud)
        self.points, self.normals = points, normals
        self.reference = Path(reference) if reference else None
        self.series = series  # "dragon" for the scaling series


def run(cmd, log, cwd=None, timeout=None):
    """Runs cmd with stdout/stderr into `log`; returns (exit code or 'timeout', seconds)."""
    start = time.monotonic()
    with open(log, "w") as out:
        try:
            # A new session, so that a timeout ends the whole process group (xvfb-run's Xvfb too).
            p = subprocess.Popen(cmd, stdout=out, stderr=subprocess.STDOUT, cwd=cwd,
                                 stdin=subprocess.DEVNULL, start_new_session=True)
            try:
                code = p.wait(timeout=timeout)
            except subprocess.TimeoutExpired:
                os.killpg(p.pid, 9)
                p.wait()
                code = "timeout"
        except OSError as e:
            out.write(f"cannot run {cmd[0]}: {e}\n")
            code = 127
    return code, time.monotonic() - start


def parse_time_v(path):
    """Wall seconds and peak RSS (MB) from a /usr/bin/time -v report."""
    wall = rss = None
    try:
        text = Path(path).read_text()
    except OSError:
        return None, None
    for line in text.splitlines():
        line = line.strip()
        if line.startswith("Elapsed (wall clock) time"):
            value = line.rsplit(" ", 1)[1]
            seconds = 0.0
            for part in value.split(":"):
                seconds = seconds * 60 + float(part)
            wall = seconds
        elif line.startswith("Maximum resident set size (kbytes)"):
            rss = int(line.rsplit(" ", 1)[1]) / 1024.0
    return wall, rss


def point_count(ply):
    with open(ply, "rb") as f:
        for raw in f:
            line = raw.decode("ascii", "replace").strip()
            if line.startswith("element vertex"):
                return int(line.split()[2])
            if line == "end_header":
                break
    return 0


def has_normals(ply):
    with open(ply, "rb") as f:
        header = b""
        for raw in f:
            header += raw
            if raw.strip() == b"end_header":
                break
    return b"property float nx" in header or b"property double nx" in header


class Runner:
    def __init__(self, args):
        self.args = args
        self.out = Path(args.out).resolve()
        self.build = Path(args.build).resolve()
        self.hrsr = self.build / "apps" / "hrsr"
        self.points_tool = self.build / "bench" / "bench_points"
        self.cgal = self.build / "bench" / "cgal_advancing_front"
        self.results_path = self.out / "results.json"
        self.results = []
        if args.resume and self.results_path.exists():
            earlier = json.loads(self.results_path.read_text())
            self.results = earlier["runs"]
            # Runs from before per-run stamps carry the date and commit of the run they came from.
            for r in self.results:
                r.setdefault("measured", {"date": earlier["meta"]["date"],
                                          "commit": earlier["meta"]["commit"]})

    # ------------------------------------------------------------------------------------------
    # Inputs

    def datasets(self):
        data = Path(self.args.data).resolve()
        inputs = self.out / "inputs"
        inputs.mkdir(parents=True, exist_ok=True)
        have_data = (data / "README.md").exists()
        if not have_data and not self.args.quick:
            sys.exit(f"compare.py: {data} not found (the full run needs ../shared/data)")
        sets = []
        if self.args.quick:
            owl = ROOT / "data" / "owl_little.ply"
            sets.append(Dataset("owl", "owl (GEL), 10k, no normals", owl, point_count(owl),
                                False))
            if have_data:
                kitten = data / "topology" / "kitten_points_genus1_normals.ply"
                sets.append(Dataset("kitten", "kitten, 5k, normals", kitten, point_count(kitten),
                                    True))
        else:
            bunny = data / "scans" / "bunny_rangescans_merged_normals.ply"
            sets.append(Dataset("bunny", "bunny range scans, 362k, normals", bunny,
                                point_count(bunny), True, data / "meshes" / "bunny_zipper.ply"))
            dragon_mesh = data / "meshes" / "dragon_vrip.ply"
            dragon = inputs / "dragon_vrip_vertices.ply"
            self.make_input(dragon, ["vertices", str(dragon_mesh), str(dragon)])
            sets.append(Dataset("dragon", "dragon vrip vertices, 437k, no normals", dragon,
                                point_count(dragon), False, dragon_mesh))
            lion = data / "scans" / "lion_takanawa_mvs_normals.ply"
            sets.append(Dataset("lion", "lion MVS cloud, 273k, normals", lion, point_count(lion),
                                True))
            kitten = data / "topology" / "kitten_points_genus1_normals.ply"
            sets.append(Dataset("kitten", "kitten, 5k, normals", kitten, point_count(kitten),
                                True))
        if have_data:
            dragon_mesh = data / "meshes" / "dragon_vrip.ply"
            for n in SCALING_QUICK if self.args.quick else SCALING_FULL:
                cloud = inputs / f"dragon_sample_{n}.ply"
                self.make_input(cloud, ["sample", str(dragon_mesh), str(n), str(cloud)])
                sets.append(Dataset(f"dragon_{n}", f"dragon surface sample, {n // 1000}k",
                                    cloud, n, True, dragon_mesh, series="dragon"))
        only = self.args.datasets.split(",") if self.args.datasets else None
        return [s for s in sets if only is None or s.name in only]

    def make_input(self, target, tool_args):
        if target.exists():
            return
        code = subprocess.call([str(self.points_tool)] + tool_args)
        if code != 0:
            sys.exit(f"compare.py: bench_points {' '.join(tool_args)} failed ({code})")

    # ------------------------------------------------------------------------------------------
    # Methods

    def command(self, method, ds, mesh, work):
        cloud = str(ds.cloud)
        if method.startswith("hrsr_p"):
            ratio = method[len("hrsr_p"):]
            return [str(self.hrsr), "reconstruct", cloud, "-o", mesh, "-q",
                    "--collapse-ratio", ratio, "--report", str(work / "report.json")]
        if method == "rsr":
            return [str(self.hrsr), "reconstruct", cloud, "-o", mesh, "-q", "--method", "rsr",
                    "--report", str(work / "report.json")]
        if method.startswith("meshlab_"):
            script = work / "script.mlx"
            name = "ball_pivoting" if method == "meshlab_bpa" else "screened_poisson"
            filters = ([] if ds.normals else [self.filters("point_normals")]) + \
                [self.filters(name)]
            script.write_text("<!DOCTYPE FilterScript>\n<FilterScript>\n" + "".join(filters) +
                              "</FilterScript>\n")
            return ["meshlabserver", "-i", cloud, "-o", mesh, "-s", str(script)]
        if method == "cgal_afront":
            return [str(self.cgal), cloud, mesh]
        if method.startswith("open3d_"):
            kind = "ball_pivoting" if method == "open3d_bpa" else "poisson"
            return [PYTHON, str(BENCH / "open3d_reconstruct.py"), kind, cloud, mesh]
        raise ValueError(method)

    @staticmethod
    def filters(name):
        text = (BENCH / "meshlab" / f"{name}.mlx").read_text()
        start, end = text.index(" <filter"), text.index("</FilterScript>")
        return text[start:end]

    def available(self, method):
        if method == "cgal_afront":
            return self.cgal.exists()
        if method.startswith("meshlab_"):
            return shutil.which("meshlabserver") and shutil.which("xvfb-run")
        if method.startswith("open3d_"):
            return subprocess.call([PYTHON, "-c", "import open3d"],
                                   stderr=subprocess.DEVNULL) == 0
        return self.hrsr.exists()

    # ------------------------------------------------------------------------------------------

    def run_one(self, ds, method):
        work = self.out / "runs" / ds.name / method
        if work.exists():
            shutil.rmtree(work)
        work.mkdir(parents=True)
        mesh = str(work / "mesh.ply")
        timing = str(work / "time.txt")
        timed = ["/usr/bin/time", "-v", "-o", timing] + self.command(method, ds, mesh, work)
        if method.startswith("meshlab_"):  # time meshlabserver only, not the X server
            timed = ["xvfb-run", "-a"] + timed
        code, outer = run(timed, work / "log.txt", cwd=work, timeout=self.args.timeout)
        wall, rss = parse_time_v(timing)
        record = {"dataset": ds.name, "label": ds.label, "series": ds.series,
                  "points": ds.points, "input_normals": ds.normals, "method": method,
                  "method_label": METHODS[method], "exit_code": code,
                  "seconds": wall if wall is not None else outer, "peak_rss_mb": rss}
        ok = code == 0 and Path(mesh).exists()
        record["status"] = "ok" if ok else ("timeout" if code == "timeout" else "failed")
        if ok:
            check = [str(self.hrsr), "check", mesh, "--input", str(ds.cloud), "--report",
                     str(work / "check.json"), "--samples", str(self.args.samples)]
            if ds.reference:
                check += ["--reference", str(ds.reference)]
            ccode, _ = run(check, work / "check_log.txt", timeout=self.args.timeout)
            if ccode == 0:
                record["check"] = json.loads((work / "check.json").read_text())
            else:
                record["status"] = "check failed"
        if not self.args.keep_meshes and Path(mesh).exists():
            os.remove(mesh)
        return record

    def save(self, meta):
        tmp = self.results_path.with_suffix(".tmp")
        tmp.write_text(json.dumps({"meta": meta, "runs": self.results}, indent=1))
        tmp.replace(self.results_path)

    def main(self):
        self.out.mkdir(parents=True, exist_ok=True)
        meta = machine_description(self.args)
        methods = self.args.methods.split(",") if self.args.methods else list(METHODS)
        for m in methods:
            if m not in METHODS:
                sys.exit(f"compare.py: unknown method {m} (known: {', '.join(METHODS)})")
        datasets = self.datasets()
        # --resume: a run outside this call's data sets and methods stays as it was (failed and
        # timed-out ones too: they are results); inside them, only successful runs are kept.
        # --again: inside them, every run is measured again.
        selected = {(ds.name, m) for ds in datasets for m in methods}
        done = {(r["dataset"], r["method"]) for r in self.results
                if (r["dataset"], r["method"]) not in selected or
                (r["status"] == "ok" and not self.args.again)}
        self.results = [r for r in self.results if (r["dataset"], r["method"]) in done]
        for ds in datasets:
            for method in methods:
                if (ds.name, method) in done:
                    continue
                if not self.available(method):
                    print(f"  {ds.name:14} {method:16} skipped (not installed)", flush=True)
                    continue
                r = self.run_one(ds, method)
                r["measured"] = {"date": meta["date"], "commit": meta["commit"]}
                self.results.append(r)
                self.save(meta)
                c = r.get("check", {})
                print(f"  {ds.name:14} {method:16} {r['status']:8} "
                      f"{r['seconds']:8.1f} s {r['peak_rss_mb'] or 0:7.0f} MB  "
                      f"F {c.get('faces', '-')}  |E_b| {c.get('boundary_edges', '-')}  "
                      f"r_v {c.get('input', {}).get('vertex_reference_ratio', '-')}", flush=True)
        self.save(meta)
        return 0


def command_output(cmd):
    try:
        return subprocess.run(cmd, capture_output=True, text=True, cwd=ROOT).stdout.strip()
    except OSError:
        return ""


def machine_description(args):
    mem_kb = 0
    with open("/proc/meminfo") as f:
        for line in f:
            if line.startswith("MemTotal"):
                mem_kb = int(line.split()[1])
    cpu = ""
    with open("/proc/cpuinfo") as f:
        for line in f:
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    os_name = ""
    if Path("/etc/os-release").exists():
        for line in Path("/etc/os-release").read_text().splitlines():
            if line.startswith("PRETTY_NAME="):
                os_name = line.split("=", 1)[1].strip('"')
    dirty = command_output(["git", "status", "--porcelain", "--untracked-files=no"])

    def version(package):
        return command_output(["dpkg-query", "-W", "-f=${Version}", package]) or "not installed"

    return {
        "mode": "quick" if args.quick else "full",
        "date": time.strftime("%Y-%m-%d"),
        "commit": command_output(["git", "rev-parse", "--short", "HEAD"]) +
                  (" (with uncommitted changes)" if dirty else ""),
        "cores": os.cpu_count(), "memory_gb": round(mem_kb / 1024 / 1024, 1), "cpu": cpu,
        "os": os_name, "kernel": platform.release(),
        "compiler": command_output(["c++", "--version"]).splitlines()[0]
        if command_output(["c++", "--version"]) else "",
        "meshlab": version("meshlab"), "cgal": version("libcgal-dev"),
        "open3d": version("python3-open3d"), "timeout_s": args.timeout,
        "check_samples": args.samples,
    }


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--build", required=True, help="build folder (apps/hrsr, bench/...)")
    p.add_argument("--data", default=str(ROOT.parent / "shared" / "data"))
    p.add_argument("--out", required=True, help="results folder")
    p.add_argument("--quick", action="store_true", help="small inputs, to test the script")
    p.add_argument("--methods", help="comma-separated subset of: " + ", ".join(METHODS))
    p.add_argument("--datasets", help="comma-separated subset of data set names")
    p.add_argument("--timeout", type=float, default=3600, help="seconds per run")
    p.add_argument("--samples", type=int, default=200000,
                   help="hrsr check --samples (area samples per surface for the distances)")
    p.add_argument("--resume", action="store_true",
                   help="keep the runs of results.json: all of those outside --datasets/--methods, "
                        "the successful ones inside (the others run again)")
    p.add_argument("--again", action="store_true",
                   help="with --resume: measure the selected runs again, successful ones too")
    p.add_argument("--keep-meshes", action="store_true", help="keep every output mesh")
    args = p.parse_args()
    if args.again and not args.resume:
        p.error("--again needs --resume (without it every run is measured anyway)")
    return Runner(args).main()


if __name__ == "__main__":
    sys.exit(main())
