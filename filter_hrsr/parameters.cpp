#include "parameters.h"

#include <vector>

namespace hrsr::plugin {
namespace {

const QStringList kMethods{"HRsR (collapse, RsR, re-expansion)", "RsR (all points)"};
const QStringList kDistances{"Tangent (smooths along normals)", "Euclidean"};
const QStringList kNormals{"Use the layer's normals (estimate if missing or unusable)",
                           "Always re-estimate (PCA + orientation)"};

/// One parameter as the user reads it: label, unit, default and meaning.
struct Doc {
    QString name, label, unit, default_text, meaning;
    bool advanced;
};

QString num(double x) {
    return QString::number(x);
}

std::vector<Doc> docs() {
    const ReconstructionOptions d; // the defaults, from vcg_ext/options.h
    const PreprocessOptions& p = d.rsr.preprocess;
    return {
        {"k", "k (neighbours)", "points", num(p.k),
         "Neighbourhood size of the candidate graph, the normal orientation and the component "
         "split.",
         false},
        {"collapse_ratio", "Collapse ratio p", "fraction of the points (0.01 to 1)",
         num(d.collapse.collapse_ratio),
         "HRsR: RsR runs on this fraction of the points, the rest are replayed as vertex splits "
         "(1 = no collapse).",
         false},
        {"l_min", "l_min (level of detail)", "length in model units (or % of the bbox diagonal)",
         num(d.reexpand.l_min),
         "HRsR: vertex splits shorter than this are not replayed, giving a coarser mesh; 0 = "
         "every point becomes a vertex.",
         false},
        {"handles", "Handles", "count", num(d.rsr.handles),
         "Topology: -1 = as many handles as the data shows, 0 = none (genus 0), g = at most g.",
         false},
        {"method", "Method", "choice", kMethods[d.method == Method::Rsr ? 1 : 0],
         "HRsR (fast, the default) or plain RsR on all points.", true},
        {"collapse_k", "Collapse neighbours", "points", num(d.collapse.collapse_k),
         "HRsR: neighbours of the collapse graph.", true},
        {"theta", "θ (normal angle)", "degrees", num(p.theta_degrees),
         "Neighbours whose normals differ by more are not linked (tangent distance).", true},
        {"r", "r (outlier cut)", "multiple of the mean neighbour distance", num(p.r),
         "Neighbour edges longer than r times the mean neighbour distance are cut; pieces "
         "smaller than " +
             num(p.min_component_size) + " points are dropped.",
         true},
        {"n", "n (shortest handle)", "point spacings", num(d.rsr.min_handle_loop),
         "Topology: a tunnel or handle is kept when the loop around it is at least n point "
         "spacings long; shorter gaps are taken for slits or noise: no handle across them, "
         "and both methods close them where they are the only holes of an otherwise closed "
         "surface. "
         "The same value works at every density and collapse ratio.",
         true},
        {"distance", "Distance", "choice",
         kDistances[p.distance == DistanceMode::Euclidean ? 1 : 0],
         "How edge lengths are measured: tangent (positions smoothed along the normals, for the "
         "algorithm only) or Euclidean.",
         true},
        {"normals", "Normals", "choice", kNormals[p.normals == NormalSource::Reestimate ? 1 : 0],
         "Use the layer's per-vertex normals (re-estimated for the whole cloud when some are "
         "zero or invalid, with a warning in the log) or always estimate them.",
         true},
        {"select_dropped", "Select dropped points", "on/off", "off",
         "Selects, in the input layer, the points that are not vertices of the mesh (and clears "
         "the selection of the others).",
         true},
    };
}

const Doc& doc(const QString& name) {
    static const std::vector<Doc> all = docs();
    for (const Doc& d : all)
        if (d.name == name) return d;
    throw MLException("HRsR: no parameter " + name); // a programming error, caught by the filter
}

QString tooltip(const Doc& d) {
    return d.meaning + " Unit: " + d.unit + ". Default: " + d.default_text + ".";
}

/// A parameter of type P built from its documentation; `values` are the type's arguments after
/// the name (default, and range or items).
template <typename P, typename... Values>
P param(const QString& name, Values&&... values) {
    const Doc& d = doc(name);
    return ml_parameter<P>(d.advanced, name, std::forward<Values>(values)..., d.label, tooltip(d));
}

} // namespace

QString worded(const InvalidOption& error) {
    const char* field = nullptr;
    switch (error.option) {
    case OptionId::K:
        field = "k";
        break;
    case OptionId::R:
        field = "r";
        break;
    case OptionId::Theta:
        field = "theta";
        break;
    case OptionId::MinHandleLoop:
        field = "n";
        break;
    case OptionId::Handles:
        field = "handles";
        break;
    case OptionId::CollapseRatio:
        field = "collapse_ratio";
        break;
    case OptionId::CollapseK:
        field = "collapse_k";
        break;
    case OptionId::LMin:
        field = "l_min";
        break;
    default:
        break; // not in the dialog
    }
    const QString name = field ? doc(field).label : QString(option_name(error.option));
    return name + " " + QString::fromStdString(error.problem);
}

void add_parameters(const MeshModel& m, RichParameterList& par) {
    const ReconstructionOptions d;
    const PreprocessOptions& p = d.rsr.preprocess;
    const float diagonal = m.cm.bbox.IsNull() ? 1.0f : float(m.cm.bbox.Diag());
    par.addParam(param<RichInt>("k", p.k));
    par.addParam(
        param<RichDynamicFloat>("collapse_ratio", float(d.collapse.collapse_ratio), 0.01f, 1.0f));
    par.addParam(param<MLRichAbsPerc>("l_min", float(d.reexpand.l_min), 0.0f, diagonal));
    par.addParam(param<RichInt>("handles", d.rsr.handles));
    par.addParam(param<RichEnum>("method", d.method == Method::Rsr ? 1 : 0, kMethods));
    par.addParam(param<RichInt>("collapse_k", d.collapse.collapse_k));
    par.addParam(param<RichFloat>("theta", float(p.theta_degrees)));
    par.addParam(param<RichFloat>("r", float(p.r)));
    par.addParam(param<RichInt>("n", int(d.rsr.min_handle_loop)));
    par.addParam(
        param<RichEnum>("distance", p.distance == DistanceMode::Euclidean ? 1 : 0, kDistances));
    par.addParam(
        param<RichEnum>("normals", p.normals == NormalSource::Reestimate ? 1 : 0, kNormals));
    par.addParam(param<RichBool>("select_dropped", false));
}

ReconstructionOptions read_options(const RichParameterList& par) {
    ReconstructionOptions o;
    o.method = par.getEnum("method") == 1 ? Method::Rsr : Method::Hrsr;
    o.rsr.preprocess.k = par.getInt("k");
    o.rsr.preprocess.theta_degrees = par.getFloat("theta");
    o.rsr.preprocess.r = par.getFloat("r");
    o.rsr.preprocess.distance =
        par.getEnum("distance") == 1 ? DistanceMode::Euclidean : DistanceMode::Tangent;
    o.rsr.preprocess.normals =
        par.getEnum("normals") == 1 ? NormalSource::Reestimate : NormalSource::Input;
    o.rsr.min_handle_loop = par.getInt("n");
    o.rsr.handles = par.getInt("handles");
    o.collapse.collapse_ratio = par.getDynamicFloat("collapse_ratio");
    o.collapse.collapse_k = par.getInt("collapse_k");
    o.reexpand.l_min = par.getAbsPerc("l_min");
    return o;
}

QString help_html() {
    QString list;
    for (const Doc& d : docs())
        list += (list.isEmpty() ? "" : " · ") + QString("<tt>") + d.name + "</tt> (" + d.unit +
                ", " + d.default_text + ")";
    return "A triangle mesh over the points of the current layer (almost every point becomes a "
           "vertex), with explicit control of the topology. <b>HRsR</b> collapses the cloud to a "
           "fraction p of its points, runs Rotation System Reconstruction on them and replays the "
           "collapses as vertex splits; <b>RsR</b> runs on all points. The result is a new layer "
           "<i>HRsR mesh</i> with per-vertex normals, and each point's colour, quality, radius, "
           "texture coordinates and custom attributes on the vertex made from it; the input "
           "layer is left as it is, except "
           "its selection with <tt>select_dropped</tt>. Faces and deleted vertices of the input "
           "are ignored. The log ends with the report (points used and dropped, r_v, boundary, "
           "genus, handles, time).<br>"
           "R. Cui, E. T. Gæde, E. Rotenberg, L. Kobbelt, J. A. Bærentzen: <i>Surface "
           "Reconstruction Using Rotation Systems</i>, ACM Transactions on Graphics 43(6), 2024, "
           "arXiv:2402.01893 (RsR). R. Cui, C. Akarsubaşı, E. T. Gæde, E. Rotenberg, L. Kobbelt, "
           "J. A. Bærentzen: <i>HRsR: Hierarchical Rotation System Reconstruction</i>, "
           "arXiv:2606.07078.<br><small>Parameters (unit, default): " +
           list + ". Advanced: all from <tt>method</tt> on.</small>";
}

} // namespace hrsr::plugin
