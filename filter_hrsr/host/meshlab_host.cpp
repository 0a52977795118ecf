// A PyMeshLab-like host for MeshLab 2022.02 and later (which have no meshlabserver): the plugin
// manager of libmeshlab-common loads MeshLab's own plugins and ours, a mesh is opened, a filter is
// applied by name with parameters and a real progress callback, and the result is saved.
// FILTER is the filter's name in MeshLab's menu or its PyMeshLab name.
//   meshlab_host PLUGIN|- FILTER --list                   every parameter: name, type, default
//   meshlab_host PLUGIN|- FILTER IN OUT [--selected FILE] [--attributes]
//                [--before|--after OTHER 'name=value;...']... [name=value ...]
// PLUGIN "-" uses only the installed plugins (after `cmake --install`). OUT gets the current
// layer after the filter with vertex normals (meshlabserver's `-m vn`), with --attributes also
// its colour, quality, radius, texture coordinates and custom attributes; --selected writes the
// indices of the selected vertices of the input layer; each --before applies the filter OTHER
// with those parameters to the input layer first, each --after to the result, in the order given
// (e.g. MeshLab's own filters that define a custom attribute, or read one into the quality).
// Exit 1 with the reason on any failure.
#include "host_parameters.h"

#include <common/globals.h>
#include <common/mlexception.h>
#include <common/plugins/plugin_manager.h>
#include <common/utilities/load_save.h>

#include <QApplication>
#include <QDir>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace {

/// Prints each change of phase or percentage (some filters crash on a null callback).
bool progress(const int percent, const char* phase) {
    static int last_percent = -1;
    static std::string last_phase;
    if (percent != last_percent || last_phase != phase)
        std::printf("progress: %3d %% %s\n", percent, phase);
    last_percent = percent;
    last_phase = phase;
    return true;
}

/// The filter called `name` in MeshLab's menu or, as PyMeshLab calls it, by its Python name.
std::pair<FilterPlugin*, QAction*> find_filter(PluginManager& pm, const QString& name) {
    for (FilterPlugin* filter : pm.filterPluginIterator())
        for (QAction* action : filter->actions())
            if (filter->filterName(action) == name || filter->pythonFilterName(action) == name)
                return {filter, action};
    throw MLException("no filter named " + name);
}

/// Applies `action` of `filter` with `par` to the current layer of `md`, printing the log.
void apply(FilterPlugin* filter, QAction* action, const RichParameterList& par, MeshDocument& md) {
    filter->setLog(&md.Log);
    md.mm()->updateDataMask(filter->getRequirements(action));
    unsigned int post_condition_mask = MeshModel::MM_UNKNOWN;
    try {
        filter->applyFilter(action, par, md, post_condition_mask, progress);
    } catch (const MLException&) {
        hrsr::host::print_log(md.Log);
        throw;
    }
    hrsr::host::print_log(md.Log);
    md.Log.clear();
}

/// Applies the filter called `name` to the current layer of `md` with `parameters`
/// ("name=value;..."; the others at their defaults).
void apply(PluginManager& pm, const QString& name, const QString& parameters, MeshDocument& md) {
    auto [filter, action] = find_filter(pm, name);
    RichParameterList par = filter->initParameterList(action, *md.mm());
    for (const QString& assignment : parameters.split(';', Qt::SkipEmptyParts))
        hrsr::host::set_parameter(par, assignment);
    apply(filter, action, par, md);
}

void run(const QStringList& args) {
    if (args.size() < 3) throw MLException("usage: meshlab_host PLUGIN|- FILTER --list | IN OUT");
    PluginManager& pm = meshlab::pluginManagerInstance();
    try { // MeshLab's own plugins (its default path is relative to the program, not the library)
        pm.loadPlugins(QDir(MESHLAB_PLUGIN_DIR));
    } catch (const MLException& e) {
        std::cerr << "warning: " << e.what() << "\n";
    }
    if (args[0] != "-") pm.loadPlugin(args[0]); // throws with the reason when refused
    auto [filter, action] = find_filter(pm, args[1]);

    MeshDocument md;
    if (args[2] == "--list") {
        MeshModel* empty = md.addNewMesh("", "empty");
        for (const RichParameter& p : filter->initParameterList(action, *empty))
            std::cout << hrsr::host::describe(p).toStdString() << "\n";
        return;
    }
    if (args.size() < 4) throw MLException("missing OUT");
    meshlab::loadMeshWithStandardParameters(args[2], md, progress);
    MeshModel* input = md.mm();
    RichParameterList par = filter->initParameterList(action, *input);
    QString selected;
    bool attributes = false;
    std::vector<std::pair<QString, QString>> after; // filter, parameters
    for (int i = 4; i < args.size(); ++i) {
        if (args[i] == "--selected" && i + 1 < args.size()) {
            selected = args[++i];
        } else if (args[i] == "--attributes") {
            attributes = true;
        } else if (args[i] == "--before" && i + 2 < args.size()) {
            apply(pm, args[i + 1], args[i + 2], md);
            i += 2;
        } else if (args[i] == "--after" && i + 2 < args.size()) {
            after.emplace_back(args[i + 1], args[i + 2]);
            i += 2;
        } else {
            hrsr::host::set_parameter(par, args[i]);
        }
    }
    apply(filter, action, par, md);
    for (const auto& [name, parameters] : after) apply(pm, name, parameters, md);
    hrsr::host::save_with_normals(pm, *md.mm(), args[3], progress, attributes);
    if (!selected.isEmpty()) {
        std::ofstream out(selected.toStdString());
        for (std::size_t i = 0; i < input->cm.vert.size(); ++i)
            if (!input->cm.vert[i].IsD() && input->cm.vert[i].IsS()) out << i << "\n";
    }
}

} // namespace

int main(int argc, char** argv) {
    QApplication app(argc, argv); // plugins make QActions; QT_QPA_PLATFORM=offscreen when headless
    try {
        run(app.arguments().mid(1));
    } catch (const MLException& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
