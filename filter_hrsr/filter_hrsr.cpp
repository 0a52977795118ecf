#include "filter_hrsr.h"

#include "layers.h"
#include "parameters.h"
#include "vertex_data.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

FilterHrsrPlugin::FilterHrsrPlugin() {
#if HRSR_ML_API >= 2022
    typeList = {FP_HRSR};
    for (ActionIDType t : types()) actionList.push_back(new QAction(filterName(t), this));
#else
    typeList << FP_HRSR;
    for (FilterIDType t : types()) actionList << new QAction(filterName(t), this);
#endif
}

QString FilterHrsrPlugin::pluginName() const {
    return "FilterHRsR";
}

QString FilterHrsrPlugin::filterName(int) const {
    return "Surface Reconstruction: HRsR";
}

QString FilterHrsrPlugin::filterInfo(int) const {
    return hrsr::plugin::help_html();
}

void FilterHrsrPlugin::fill_parameters(const MeshModel& m, RichParameterList& par) const {
    hrsr::plugin::add_parameters(m, par);
}

void FilterHrsrPlugin::run(MeshDocument& md, const RichParameterList& par, vcg::CallBackPos* cb) {
    MeshModel* input = md.mm();
    if (input == nullptr) throw std::invalid_argument("no current layer");
    const hrsr::ReconstructionOptions o = hrsr::plugin::read_options(par);
    hrsr::validate(o); // a clear message naming the option, before any work

    hrsr::plugin::LayerPoints points = hrsr::plugin::points_of(input->cm);
    // Progress per phase, from the calling (main) thread only: the core never calls it from
    // its worker threads.
    hrsr::Progress progress([cb](const std::string& phase, double fraction) {
        if (cb) cb(int(100 * fraction), phase.c_str());
        return true; // MeshLab 2020.09 cannot cancel
    });
    const auto start = std::chrono::steady_clock::now();
    hrsr::ReconstructionReport report;
    const hrsr::Reconstruction mesh = hrsr::reconstruct(points.cloud, o, {0, &progress}, report);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    MeshModel* out = md.addNewMesh("", "HRsR mesh", false);
    hrsr::plugin::fill_layer(points, mesh, out->cm);
    for (const std::string& name :
         hrsr::plugin::copy_vertex_data(*input, hrsr::plugin::vertex_sources(points, mesh), *out))
        log_message("HRsR: the per-vertex attribute %s is not carried to the mesh: its type is "
                    "not one the filter knows",
                    name.c_str());
    md.setCurrentMesh(out->id());
    for (const std::string& w : report.preprocess.warnings)
        log_message("HRsR warning: %s", w.c_str());
    if (report.preprocess.input_normals_look_inconsistent)
        log_message("HRsR hint: Normals = \"Always re-estimate\" ignores the layer's normals");
    if (par.getBool("select_dropped")) {
        const std::size_t selected = hrsr::plugin::select_dropped(points, mesh, report);
        log_message("HRsR: %zu points not in the mesh are selected in layer %s", selected,
                    input->label().toStdString().c_str());
    }
    log_summary(report, seconds);
}

void FilterHrsrPlugin::log_summary(const hrsr::ReconstructionReport& r, double seconds) {
    const hrsr::MeshStats& m = r.mesh;
    QString genus;
    for (const hrsr::ComponentTopology& c : m.components)
        if (c.closed()) genus += (genus.isEmpty() ? "" : ", ") + QString::number(c.genus());
    log_message("HRsR: %zu input points, %zu used, %zu not in the mesh (%zu non-finite, %zu in "
                "small components, %zu not in any triangle, %zu in folds, %zu merged into other "
                "vertices); %zu duplicates merged; r_v = %.4f %%",
                r.preprocess.input_points, r.points_used,
                r.preprocess.input_points - r.referenced_input_points,
                r.preprocess.count(hrsr::PointFate::NonFinite),
                r.preprocess.count(hrsr::PointFate::SmallComponent) +
                    r.dropped_small_coarse_component.size(),
                r.not_in_triangle.size(), r.dropped_fold.size(), r.merged_points,
                r.preprocess.count(hrsr::PointFate::Duplicate), 100.0 * r.vertex_reference_ratio);
    const hrsr::ComponentTopology* largest = hrsr::largest_component(m);
    log_message("HRsR: %zu vertices, %zu triangles, %zu boundary edges in %zu loops, %zu "
                "non-manifold edges, %zu components (genus of closed ones: %s), largest of genus "
                "%ld with %zu boundary loops, %zu handles, %.2f s",
                m.vertices, m.faces, m.boundary_edges, m.boundary_loops, m.non_manifold_edges,
                m.components.size(), genus.isEmpty() ? "none" : genus.toStdString().c_str(),
                largest ? largest->genus() : 0L, largest ? largest->boundary_loops : 0, r.handles,
                seconds);
    if (!r.handle_hop_limits.empty()) {
        const auto [lo, hi] =
            std::minmax_element(r.handle_hop_limits.begin(), r.handle_hop_limits.end());
        log_message("HRsR: handles kept where the loop around them is at least n point spacings: "
                    "%zu to %zu graph hops on the cloud RsR saw",
                    *lo, *hi);
    }
    if (r.preprocess.denoised && r.coarse_points > 0)
        log_message("HRsR: the cloud's noise is %.2f point spacings, so the collapse and the "
                    "re-expansion worked on smoothed positions (D-33); the vertices keep the "
                    "input's",
                    r.preprocess.relative_noise);
    else if (r.preprocess.denoised)
        log_message("HRsR: the cloud's noise is %.2f point spacings, so RsR used the layer's "
                    "normals averaged over the smoothing neighbourhood (D-33)",
                    r.preprocess.relative_noise);
    log_message("HRsR: fold repair (D-26, D-32): %zu intersecting triangle pairs, %zu edge "
                "flips, %zu pairs left; %zu vertices taken out (%zu holes filled again), %zu "
                "faces cut, %zu pairs left; %zu points in no triangle placed into a face (D-37); "
                "%zu small holes closed (D-38), %zu slits closed (D-48); %zu small pieces (%zu "
                "points) joined the surface they lie on (D-55), %zu of them closing the hole they "
                "lay in (D-56)",
                r.fold_repair.pairs_before, r.fold_repair.flips, r.fold_repair.pairs_after,
                r.fold_removal.vertices_removed, r.fold_removal.holes_refilled,
                r.fold_removal.faces_cut, r.fold_removal.pairs_after, r.fold_removal.points_placed,
                r.fold_removal.small_holes_closed, r.fold_removal.slits_closed,
                r.fold_removal.pieces_absorbed, r.fold_removal.points_absorbed,
                r.fold_removal.piece_holes_closed);
    if (r.fold_removal.faces_against_normals > 0)
        log_message("HRsR: %zu faces winding against their normals (D-64, D-65): %zu edges "
                    "flipped, %zu fans refilled, %zu left",
                    r.fold_removal.faces_against_normals, r.fold_removal.facing_flips,
                    r.fold_removal.facing_refills, r.fold_removal.faces_against_normals_left);
    if (r.flat_faces.found > 0)
        log_message("HRsR: %zu faces without area (corners on one line, D-36): %zu edges flipped, "
                    "%zu taken off the border, %zu left",
                    r.flat_faces.found, r.flat_faces.flipped, r.flat_faces.removed,
                    r.flat_faces.left);
}

// A new layer is added; the input only changes its selection (select_dropped). MM_VERTNUMBER
// turns off the dialog's Preview, which would add a layer at every change of a parameter.
constexpr int kPostCondition = MeshModel::MM_VERTFLAGSELECT | MeshModel::MM_VERTNUMBER;

#if HRSR_ML_API >= 2022
FilterHrsrPlugin::FilterClass FilterHrsrPlugin::getClass(const QAction*) const {
    return FilterClass(Remeshing | PointSet);
}
int FilterHrsrPlugin::getPreConditions(const QAction*) const {
    return MeshModel::MM_NONE;
}
int FilterHrsrPlugin::getRequirements(const QAction*) {
    return MeshModel::MM_NONE;
}
int FilterHrsrPlugin::postCondition(const QAction*) const {
    return kPostCondition;
}
RichParameterList FilterHrsrPlugin::initParameterList(const QAction*, const MeshModel& m) {
    RichParameterList p;
    fill_parameters(m, p);
    return p;
}
std::map<std::string, QVariant> FilterHrsrPlugin::applyFilter(const QAction* a,
                                                              const RichParameterList& par,
                                                              MeshDocument& md, unsigned int&,
                                                              vcg::CallBackPos* cb) {
    if (ID(a) != FP_HRSR) wrongActionCalled(a);
    try {
        run(md, par, cb);
    } catch (const MLException&) {
        throw;
    } catch (const hrsr::InvalidOption& e) {
        throw MLException("HRsR: " + hrsr::plugin::worded(e));
    } catch (const std::exception& e) {
        throw MLException(QString("HRsR: ") + e.what());
    }
    return {};
}
QString FilterHrsrPlugin::pythonFilterName(ActionIDType) const {
    return "generate_surface_reconstruction_hrsr";
}
#else
FilterHrsrPlugin::FilterClass FilterHrsrPlugin::getClass(QAction*) {
    return FilterClass(Remeshing | PointSet);
}
int FilterHrsrPlugin::getPreConditions(QAction*) const {
    return MeshModel::MM_NONE;
}
int FilterHrsrPlugin::getRequirements(QAction*) {
    return MeshModel::MM_NONE;
}
int FilterHrsrPlugin::postCondition(QAction*) const {
    return kPostCondition;
}
void FilterHrsrPlugin::initParameterSet(QAction*, MeshModel& m, RichParameterList& par) {
    fill_parameters(m, par);
}
bool FilterHrsrPlugin::applyFilter(QAction* a, MeshDocument& md, const RichParameterList& par,
                                   vcg::CallBackPos* cb) {
    if (ID(a) != FP_HRSR) {
        errorMessage = "unknown action";
        return false;
    }
    try { // nothing may escape: an exception or an abort would take MeshLab down
        run(md, par, cb);
    } catch (const hrsr::InvalidOption& e) {
        const QString reason = hrsr::plugin::worded(e);
        errorMessage = "HRsR: " + reason;
        Log(GLLogStream::SYSTEM, "HRsR failed: %s", qUtf8Printable(reason));
        return false;
    } catch (const std::exception& e) { // hrsr errors, MLException, bad_alloc, vcg exceptions
        errorMessage = QString("HRsR: ") + e.what();
        Log(GLLogStream::SYSTEM, "HRsR failed: %s", e.what()); // meshlabserver only prints the log
        return false;
    }
    return true;
}
#endif

MESHLAB_PLUGIN_NAME_EXPORTER(FilterHrsrPlugin)
