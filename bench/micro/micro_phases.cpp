// Google Benchmark of the reconstruction phases on synthetic tori (default 100k and 1M points):
//   micro_phases [--sizes=100000,1000000] [Google Benchmark flags]
// Each benchmark times one phase; the phases before it run untimed (PauseTiming) in every
// iteration, since each phase changes the state it starts from. Pre-processing is not timed
// here except the PCA normals (the clouds come with exact normals and serve as their own
// smoothed positions). Phases that are not callable alone are timed through the nearest entry
// point: "collapse" is hrsr::collapse() (graph, queue and records), "reexpansion" is
// hrsr::replay_collapses() (splits, crossings and flips together), "ears" includes the
// small-hole closing that follows.
#include "phase_setup.h"

#include "graph/neighbour_graph.h"
#include "preprocess/pca_normals.h"

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

using namespace hrsr;
using namespace hrsr::bench;

std::size_t size_of(const benchmark::State& state) {
    return std::size_t(state.range(0));
}

void knn_graph(benchmark::State& state) {
    const rsr::ComponentCloud& c = torus_cloud(size_of(state));
    for (auto _ : state) {
        const KnnIndex index(c.smoothed);
        const CsrGraph g = symmetric_union(knn_table(index, 70, {}), c.smoothed.size(), {});
        benchmark::DoNotOptimize(g.adjacency.data());
    }
}

void pca_normals(benchmark::State& state) {
    const rsr::ComponentCloud& c = torus_cloud(size_of(state));
    const KnnIndex index(c.positions);
    for (auto _ : state) {
        const PcaNormals n =
            estimate_normals(c.positions, index, neighbour_count(c.positions.size(), 0), {});
        benchmark::DoNotOptimize(n.normals.data());
    }
}

/// One RsR phase; the phases before it run untimed in every iteration.
void rsr_phase(benchmark::State& state, RsrPhase phase) {
    const rsr::ComponentCloud& c = torus_cloud(size_of(state));
    for (auto _ : state) {
        state.PauseTiming();
        RsrState s(c);
        s.run_until(phase);
        state.ResumeTiming();
        s.run(phase);
        benchmark::DoNotOptimize(s.triangles.data());
    }
}

void collapse_phase(benchmark::State& state) {
    const rsr::ComponentCloud& c = torus_cloud(size_of(state));
    for (auto _ : state) {
        const CollapsedCloud r = collapse(c.positions, c.normals, CollapseOptions{}, {});
        benchmark::DoNotOptimize(r.records.data());
    }
}

void reexpansion(benchmark::State& state) {
    const rsr::ComponentCloud& c = torus_cloud(size_of(state));
    for (auto _ : state) {
        state.PauseTiming();
        const ReexpansionStart m = reexpansion_start(c, CollapseOptions{});
        ReexpansionStats stats;
        std::vector<CollapseRecord> records = m.collapsed.records; // consumed by the replay
        const ReexpandOptions options;
        state.ResumeTiming();
        const ReexpandedMesh fine = replay_collapses(
            {c.positions, c.normals, m.mesh, std::move(records), options, 0.0}, {}, stats);
        benchmark::DoNotOptimize(fine.triangles.data());
    }
}

/// Removes "--sizes=a,b,..." from argv; returns the sizes (default 100k and 1M).
std::vector<long> take_sizes(int& argc, char** argv) {
    std::vector<long> sizes = {100000, 1000000};
    for (int i = 1; i < argc; ++i) {
        if (std::strncmp(argv[i], "--sizes=", 8) != 0) continue;
        sizes.clear();
        for (const char* p = argv[i] + 8; *p != '\0';) {
            char* end = nullptr;
            const long n = std::strtol(p, &end, 10);
            if (end == p || n < 100) return {};
            sizes.push_back(n);
            p = *end == ',' ? end + 1 : end;
        }
        for (int j = i; j + 1 < argc; ++j) argv[j] = argv[j + 1];
        --argc;
        break;
    }
    return sizes;
}

} // namespace

int main(int argc, char** argv) {
    const std::vector<long> sizes = take_sizes(argc, argv);
    if (sizes.empty()) {
        std::fprintf(stderr, "micro_phases: --sizes must list point counts >= 100\n");
        return 2;
    }
    const auto add = [&sizes](const char* name, auto&& function) {
        for (long n : sizes)
            benchmark::RegisterBenchmark(name, function)
                ->Arg(n)
                ->Unit(benchmark::kMillisecond)
                ->UseRealTime();
    };
    add("knn_graph", knn_graph);
    add("normals_pca", pca_normals);
    const std::pair<const char*, RsrPhase> rsr_phases[] = {
        {"candidate_graph", RsrPhase::CandidateGraph},
        {"mst", RsrPhase::SpanningTree},
        {"face_split", RsrPhase::FaceSplit},
        {"handles", RsrPhase::Handles},
        {"ears", RsrPhase::Ears}};
    for (const auto& [name, phase] : rsr_phases)
        add(name, [phase = phase](benchmark::State& state) { rsr_phase(state, phase); });
    add("collapse", collapse_phase);
    add("reexpansion", reexpansion);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
