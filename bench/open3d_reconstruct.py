#!/usr/bin/env python3
"""Open3D reconstructions for bench/compare.sh (Debian python3-open3d).

usage: open3d_reconstruct.py {ball_pivoting,poisson} CLOUD.ply OUT.ply

* Normals: the input's if it has them, else Open3D's estimate_normals (30 nearest neighbours)
  and orient_normals_consistent_tangent_plane(30).
* ball_pivoting: radii 1, 2 and 4 times the mean nearest-neighbour distance (the usual recipe
  in Open3D's documentation).
* poisson: create_from_point_cloud_poisson at depth 10 (as the MeshLab run), no density
  trimming (a watertight surface, as MeshLab's Screened Poisson gives).
Exit codes: 0 success, 1 failure, 2 usage.
"""
import sys


def main(argv):
    if len(argv) != 4 or argv[1] not in ("ball_pivoting", "poisson"):
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    import numpy as np
    import open3d as o3d

    method, source, target = argv[1:]
    cloud = o3d.io.read_point_cloud(source)
    if len(cloud.points) == 0:
        print(f"open3d_reconstruct: {source}: no points", file=sys.stderr)
        return 1
    if not cloud.has_normals():
        cloud.estimate_normals(o3d.geometry.KDTreeSearchParamKNN(knn=30))
        cloud.orient_normals_consistent_tangent_plane(30)
    if method == "ball_pivoting":
        spacing = float(np.mean(cloud.compute_nearest_neighbor_distance()))
        radii = o3d.utility.DoubleVector([spacing, 2 * spacing, 4 * spacing])
        mesh = o3d.geometry.TriangleMesh.create_from_point_cloud_ball_pivoting(cloud, radii)
    else:
        mesh, _densities = o3d.geometry.TriangleMesh.create_from_point_cloud_poisson(
            cloud, depth=10)
    if len(mesh.triangles) == 0:
        print(f"open3d_reconstruct: {method} made no triangle", file=sys.stderr)
        return 1
    if not o3d.io.write_triangle_mesh(target, mesh, write_ascii=False):
        print(f"open3d_reconstruct: cannot write {target}", file=sys.stderr)
        return 1
    print(f"open3d_reconstruct {method}: {len(cloud.points)} points, "
          f"{len(mesh.vertices)} vertices, {len(mesh.triangles)} triangles")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
