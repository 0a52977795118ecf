// Counts the report gives for the phases that edit the output mesh: the fold repair (both
// methods) and HRsR's re-expansion. Plain structs, part of the public API (reconstruction.h);
// mesh/fold_repair.h and hrsr/reexpansion.h, which fill them, include this header.
#pragma once

#include <chrono>
#include <cstddef>

namespace hrsr {

/// D-26 (mesh/fold_repair.h), on the output mesh.
struct FoldRepairStats {
    std::size_t pairs_before = 0; ///< intersecting triangle pairs when the repair started
    std::size_t pairs_after = 0;  ///< left when it stopped
    std::size_t flips = 0;
    std::size_t rounds = 0; ///< rounds that flipped at least one edge
};

/// D-32 (mesh/fold_removal.h): what the flips left, removed, on the coordinates as written.
struct FoldRemovalStats {
    std::size_t pairs_before = 0;        ///< intersecting triangle pairs after the flips
    std::size_t pairs_after = 0;         ///< pairs with both faces still in the mesh (0)
    std::size_t vertices_removed = 0;    ///< vertices taken out with their fans (and not put back)
    std::size_t vertices_reinserted = 0; ///< taken out, then put back into a face of the fill
    std::size_t holes_refilled = 0;      ///< holes of those fans triangulated again
    std::size_t faces_cut = 0;           ///< faces taken out without a fill (the last resort)
    std::size_t vertex_copies = 0;       ///< made where a cut pinched a vertex (§5.8)
    std::size_t points_placed = 0;       ///< points in no triangle put into a face (D-37)
    /// Of the vertices put back and points placed, those that joined a border edge: the border
    /// runs through them, one edge more each (D-41).
    std::size_t points_joined_border = 0;
    std::size_t small_holes_closed = 0; ///< loops of ≤ 5 edges that D-28 left, closed (D-38)
    std::size_t slits_closed = 0;       ///< border loops narrower than 1.5 spacings, closed (D-48)
    std::size_t pieces_absorbed = 0;    ///< small pieces whose points went into a surface (D-55)
    std::size_t points_absorbed = 0;    ///< their points put into faces (a pinched copy is not)
    std::size_t piece_holes_closed = 0; ///< of them, pieces in a hole that was closed (D-56)
    /// D-64, last: faces winding against their corners' normals, edges flipped to turn them,
    /// fans refilled around a corner put back where no flip did (D-65), and the faces left so.
    std::size_t faces_against_normals = 0;
    std::size_t facing_flips = 0;
    std::size_t facing_refills = 0;
    std::size_t faces_against_normals_left = 0;
};

/// D-36 (mesh/flat_faces.h): faces with collinear corners in the coordinates as written.
struct FlatFaceStats {
    std::size_t found = 0;   ///< flat faces in the mesh after D-32
    std::size_t flipped = 0; ///< cleared by flipping their longest edge
    std::size_t removed = 0; ///< cleared by removing them from the border
    std::size_t left = 0;    ///< neither possible (runs of four collinear points)
};

/// D-42, D-43: how evenly the tiles' work was spread. Tiles run in stretches (a collapse step,
/// a stretch of records inside tiles) that end together, so a stretch lasts as long as its
/// slowest tile: on many cores the phase's tile work takes about `slowest` seconds, on one
/// `work`. Wall-clock times, so they vary from run to run (the result does not).
struct TileTimes {
    std::size_t tiles = 1;
    std::size_t stretches = 0;
    double work = 0;    ///< seconds, all tiles of all stretches
    double slowest = 0; ///< seconds, the slowest tile of each stretch, summed
    double mean = 0;    ///< seconds, the mean tile of each stretch (over its busy tiles), summed
    /// Adds one stretch's per-tile seconds.
    void add_stretch(const double* seconds, std::size_t busy) {
        if (busy == 0) return;
        double sum = 0, most = 0;
        for (std::size_t i = 0; i < busy; ++i) {
            sum += seconds[i];
            most = seconds[i] > most ? seconds[i] : most;
        }
        ++stretches;
        work += sum;
        slowest += most;
        mean += sum / double(busy);
    }
    /// Slowest over mean tile, summed over stretches (1: perfectly even; 0 without tiles).
    double balance() const { return mean > 0 ? slowest / mean : 0; }
    /// Runs one tile's work of a stretch; returns its wall-clock seconds.
    template <class Work>
    static double seconds_of(Work&& work) {
        const auto start = std::chrono::steady_clock::now();
        work();
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
};

/// HRsR's re-expansion (hrsr/reexpansion.h, ALGORITHM.md §8).
struct ReexpansionStats {
    std::size_t records = 0;           ///< collapse records available
    std::size_t replayed = 0;          ///< splits performed
    std::size_t skipped_no_vertex = 0; ///< node never reached the mesh: its latent point is dropped
    std::size_t failed_no_pair = 0;    ///< no split pair: latent aliased to the kept vertex (D-16)
    std::size_t unresolved_crossings = 0; ///< splits done with a crossing left
    std::size_t crossing_flips = 0, triangles_removed = 0, improvement_flips = 0;
    std::size_t merged_by_l_min = 0;       ///< latent points aliased because of l_min
    std::size_t border_slivers_peeled = 0; ///< D-34: coarse border slivers removed first
    std::size_t border_splits = 0;         ///< D-34: splits that put the new vertex on the border
    std::size_t tiles = 1;                 ///< D-43: tiles replayed in parallel
    std::size_t replayed_in_tiles = 0;     ///< D-43: records replayed by their tile's thread
    std::size_t deferred_at_tile_borders = 0; ///< D-43: reached another tile: replayed after
    std::size_t late_replayed_in_groups = 0;  ///< D-49: of those, replayed by groups of tiles
    TileTimes tile_times;                     ///< D-43
    bool stopped_at_l_min = false;
};

} // namespace hrsr
