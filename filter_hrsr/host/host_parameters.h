// What meshlab_host does with MeshLab's parameter, log and save interfaces, kept apart from its
// command line. PyMeshLab does the same conversions between its arguments and RichParameters.
#pragma once

#include <common/GLLogStream.h>
#include <common/parameters/rich_parameter_list.h>
#include <common/plugins/plugin_manager.h>

namespace hrsr::host {

/// "name<TAB>type<TAB>default<TAB>label", an enum's default as its text.
QString describe(const RichParameter& p);

/// Sets one "name=value" argument, converted to the parameter's own value type; throws
/// MLException naming the parameter when there is no such parameter or the value does not parse.
void set_parameter(RichParameterList& par, const QString& assignment);

/// Prints every log line, "log: " first.
void print_log(const GLLogStream& log);

/// Saves `m` to `file` (format from its suffix) with vertex normals only, like meshlabserver's
/// `-m vn`, so that a PLY is written the way the CLI writes it; with `everything`, also the
/// per-vertex colour, quality, radius and texture coordinates the layer has and every custom
/// per-vertex attribute the format's exporter offers to save.
void save_with_normals(PluginManager& pm, MeshModel& m, const QString& file, vcg::CallBackPos* cb,
                       bool everything = false);

} // namespace hrsr::host
