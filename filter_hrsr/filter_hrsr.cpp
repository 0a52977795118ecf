#include "filter_hrsr.h"

#include "reconstruction.h"

#include <vcg/complex/allocate.h>

#include <chrono>
#include <cmath>
#include <stdexcept>

namespace {

const QStringList kMethods{"HRsR (collapse, RsR, re-expansion)", "RsR (all points)"};
const QStringList kDistances{"Tangent (smooths along normals)", "Euclidean"};
const QStringList kNormals{"Use the layer's normals (estimate if missing or unusable)",
                           "Always re-estimate (PCA + orientation)"};

// The layer's live vertices, with their normals (MeshLab always has per-vertex normals; unset
// ones are zero and the core falls back to estimation for the whole cloud, with a warning).
hrsr::PointSet point_set_of(const CMeshO& m, std::vector<const CVertexO*>& vertices) {
    hrsr::PointSet s;
    s.precision = hrsr::CoordinatePrecision::Float;
    for (const CVertexO& v : m.vert) {
        if (v.IsD()) continue;
        vertices.push_back(&v);
        s.positions.emplace_back(v.cP()[0], v.cP()[1], v.cP()[2]);
        s.normals.emplace_back(v.cN()[0], v.cN()[1], v.cN()[2]);
    }
    return s;
}

} // namespace

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
    const hrsr::ReconstructionOptions d;
    return QString(
               "Reconstructs a triangle mesh whose vertices are the points of the current layer "
               "(almost all of them are kept), with explicit control of the topology. "
               "<b>HRsR</b> collapses the cloud to a fraction of its points, runs Rotation System "
               "Reconstruction on them and replays the collapses as vertex splits; <b>RsR</b> runs "
               "on "
               "all points. The result is a new layer <i>HRsR mesh</i>; the input cloud is left as "
               "it is."
               "<br><br>References: Cui, Bærentzen et al., <i>Rotation System Reconstruction</i> "
               "(RsR, "
               "2024) and its hierarchical version <i>HRsR</i>. Defaults: k = %1, collapse ratio = "
               "%2, "
               "l_min = 0 (full detail), handles = %3 (as many as found), n = %4, θ = %5°, r = %6.")
        .arg(d.rsr.preprocess.k)
        .arg(d.collapse.collapse_ratio)
        .arg(d.rsr.handles)
        .arg(d.rsr.max_handle_hops)
        .arg(d.rsr.preprocess.theta_degrees)
        .arg(d.rsr.preprocess.r);
}

void FilterHrsrPlugin::fill_parameters(const MeshModel& m, RichParameterList& par) const {
    const hrsr::ReconstructionOptions d; // defaults come from the core's options header
    const float diagonal = m.cm.bbox.IsNull() ? 1.0f : float(m.cm.bbox.Diag());
    par.addParam(
        RichInt("k", d.rsr.preprocess.k, "k (neighbours)",
                "Neighbourhood size for the candidate graph, orientation and component split "
                "(points). Default " +
                    QString::number(d.rsr.preprocess.k) + "."));
    par.addParam(RichDynamicFloat(
        "collapse_ratio", float(d.collapse.collapse_ratio), 0.01f, 1.0f, "Collapse ratio p",
        "HRsR: fraction of the points RsR runs on (1 = no collapse). Default " +
            QString::number(d.collapse.collapse_ratio) + " (12.5 %)."));
    par.addParam(
        MLRichAbsPerc("l_min", 0.0f, 0.0f, diagonal, "l_min (level of detail)",
                      "HRsR: vertex splits shorter than this length are not replayed; 0 = every "
                      "point is a vertex. In model units, or % of the bounding-box diagonal."));
    par.addParam(RichInt("handles", d.rsr.handles, "Handles",
                         "-1 = as many as the data shows, 0 = none (genus 0), g = at most g."));
    par.addParam(RichEnum("method", 0, kMethods, "Method", "HRsR (default) or plain RsR."));
    par.addParam(RichInt("collapse_k", d.collapse.collapse_k, "Collapse neighbours",
                         "HRsR: neighbours of the collapse graph. Default " +
                             QString::number(d.collapse.collapse_k) + "."));
    par.addParam(RichFloat("theta", float(d.rsr.preprocess.theta_degrees), "θ (degrees)",
                           "Neighbours whose normals differ by more are not linked. Default " +
                               QString::number(d.rsr.preprocess.theta_degrees) + "°."));
    par.addParam(
        RichFloat("r", float(d.rsr.preprocess.r), "r (outlier cut)",
                  "Edges longer than r × the mean neighbour distance are cut; small pieces "
                  "are dropped. Default " +
                      QString::number(d.rsr.preprocess.r) + "."));
    par.addParam(
        RichInt("n", d.rsr.max_handle_hops, "n (handle hops)",
                "Handles only join points more than n graph hops apart; lower it (e.g. 20) "
                "for clouds of a few thousand points. Default " +
                    QString::number(d.rsr.max_handle_hops) + "."));
    par.addParam(
        RichEnum("distance", 0, kDistances, "Distance", "Tangent (default) or Euclidean."));
    par.addParam(
        RichEnum("normals", 0, kNormals, "Normals", "Use the layer's normals or re-estimate."));
    par.addParam(
        RichBool("select_dropped", false, "Select dropped points",
                 "Select, in the input layer, the points that are not vertices of the mesh."));
}

void FilterHrsrPlugin::run(MeshDocument& md, const RichParameterList& par, vcg::CallBackPos* cb) {
    MeshModel* input = md.mm();
    if (input == nullptr) throw std::invalid_argument("no current layer");
    hrsr::ReconstructionOptions o;
    o.method = par.getEnum("method") == 1 ? hrsr::Method::Rsr : hrsr::Method::Hrsr;
    o.rsr.preprocess.k = par.getInt("k");
    o.rsr.preprocess.theta_degrees = par.getFloat("theta");
    o.rsr.preprocess.r = par.getFloat("r");
    o.rsr.preprocess.distance =
        par.getEnum("distance") == 1 ? hrsr::DistanceMode::Euclidean : hrsr::DistanceMode::Tangent;
    o.rsr.preprocess.normals =
        par.getEnum("normals") == 1 ? hrsr::NormalSource::Reestimate : hrsr::NormalSource::Input;
    o.rsr.max_handle_hops = par.getInt("n");
    o.rsr.handles = par.getInt("handles");
    o.collapse.collapse_ratio = par.getDynamicFloat("collapse_ratio");
    o.collapse.collapse_k = par.getInt("collapse_k");
    o.reexpand.l_min = par.getAbsPerc("l_min");
    hrsr::validate(o); // a clear message naming the option, before any work

    std::vector<const CVertexO*> vertices;
    const hrsr::PointSet cloud = point_set_of(input->cm, vertices);
    // Progress from the calling (main) thread only: the core never calls it from workers.
    hrsr::Progress progress([cb](const std::string& phase, double fraction) {
        if (cb) cb(int(100 * fraction), phase.c_str());
        return true; // MeshLab 2020.09 cannot cancel
    });
    const auto start = std::chrono::steady_clock::now();
    hrsr::ReconstructionReport report;
    const hrsr::Reconstruction mesh = hrsr::reconstruct(cloud, o, {0, &progress}, report);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    MeshModel* out = md.addNewMesh("", "HRsR mesh", false);
    auto v = vcg::tri::Allocator<CMeshO>::AddVertices(out->cm, mesh.vertex_input_index.size());
    for (std::size_t k = 0; k < mesh.vertex_input_index.size(); ++k, ++v) {
        v->P() = vertices[mesh.vertex_input_index[k]]->cP(); // the input point, bit-exact
        const hrsr::Vec3& n = mesh.vertex_normals[k];
        v->N() = CMeshO::CoordType(float(n[0]), float(n[1]), float(n[2]));
    }
    auto f = vcg::tri::Allocator<CMeshO>::AddFaces(out->cm, mesh.triangles.size());
    for (const hrsr::Triangle& t : mesh.triangles) {
        for (int k = 0; k < 3; ++k) f->V(k) = &out->cm.vert[t[k]];
        ++f;
    }
    vcg::tri::UpdateBounding<CMeshO>::Box(out->cm);
    vcg::tri::UpdateNormal<CMeshO>::PerFaceNormalized(out->cm); // keep the point normals per vertex
    md.setCurrentMesh(out->id());

    if (par.getBool("select_dropped")) {
        std::vector<char> used(vertices.size(), 0);
        for (std::uint32_t i : mesh.vertex_input_index) used[i] = 1;
        for (std::size_t i = 0; i < vertices.size(); ++i) {
            CVertexO* vp = const_cast<CVertexO*>(vertices[i]);
            if (used[i])
                vp->ClearS();
            else
                vp->SetS();
        }
    }

    for (const std::string& w : report.preprocess.warnings)
        log_message("HRsR warning: %s", w.c_str());
    const hrsr::MeshStats& m = report.mesh;
    QString genus;
    for (const hrsr::ComponentTopology& c : m.components)
        if (c.closed()) genus += (genus.isEmpty() ? "" : ", ") + QString::number(c.genus());
    log_message(
        "HRsR: %zu input points, %zu used, %zu not in any triangle, %zu merged; r_v = %.4f %%",
        report.preprocess.input_points, report.points_used, report.not_in_triangle.size(),
        report.merged_points + report.preprocess.count(hrsr::PointFate::Duplicate),
        100.0 * report.vertex_reference_ratio);
    log_message(
        "HRsR: %zu vertices, %zu triangles, %zu boundary edges in %zu loops, %zu components "
        "(genus of closed ones: %s), %zu handles, %.2f s",
        m.vertices, m.faces, m.boundary_edges, m.boundary_loops, m.components.size(),
        genus.isEmpty() ? "none" : genus.toStdString().c_str(), report.handles, seconds);
}

#if HRSR_ML_API >= 2022
MeshFilterInterface::FilterClass FilterHrsrPlugin::getClass(const QAction*) const {
    return FilterClass(Remeshing | PointSet);
}
int FilterHrsrPlugin::getPreConditions(const QAction*) const {
    return MeshModel::MM_NONE;
}
int FilterHrsrPlugin::getRequirements(const QAction*) {
    return MeshModel::MM_NONE;
}
int FilterHrsrPlugin::postCondition(const QAction*) const {
    return MeshModel::MM_NONE;
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
    } catch (const std::exception& e) {
        throw MLException(QString("HRsR: ") + e.what());
    }
    return {};
}
QString FilterHrsrPlugin::pythonFilterName(ActionIDType) const {
    return "generate_surface_reconstruction_hrsr";
}
#else
MeshFilterInterface::FilterClass FilterHrsrPlugin::getClass(QAction*) {
    return FilterClass(Remeshing | PointSet);
}
int FilterHrsrPlugin::getPreConditions(QAction*) const {
    return MeshModel::MM_NONE;
}
int FilterHrsrPlugin::getRequirements(QAction*) {
    return MeshModel::MM_NONE;
}
// A new layer is added; the input is only changed in its selection (select_dropped).
int FilterHrsrPlugin::postCondition(QAction*) const {
    return MeshModel::MM_VERTFLAGSELECT;
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
    } catch (const std::exception& e) { // hrsr errors, MLException, bad_alloc, vcg exceptions
        errorMessage = QString("HRsR: ") + e.what();
        Log(GLLogStream::SYSTEM, "HRsR failed: %s", e.what()); // meshlabserver only prints the log
        return false;
    }
    return true;
}
#endif

MESHLAB_PLUGIN_NAME_EXPORTER(FilterHrsrPlugin)
