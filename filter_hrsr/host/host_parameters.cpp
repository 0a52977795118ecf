#include "host_parameters.h"

#include <common/mlexception.h>

#include <iostream>

namespace hrsr::host {

QString describe(const RichParameter& p) {
    const Value& v = p.value();
    QString value;
    if (const auto* e = dynamic_cast<const RichEnum*>(&p))
        value = e->enumvalues.value(v.getInt());
    else if (v.isBool())
        value = v.getBool() ? "true" : "false";
    else if (v.isInt())
        value = QString::number(v.getInt());
    else if (v.isFloat())
        value = QString::number(double(v.getFloat()));
    else if (v.isString())
        value = v.getString();
    return p.name() + "\t" + p.stringType() + "\t" + value + "\t" + p.fieldDescription();
}

void set_parameter(RichParameterList& par, const QString& assignment) {
    const int eq = assignment.indexOf('=');
    const QString name = assignment.left(eq), text = assignment.mid(eq + 1);
    if (eq <= 0 || !par.hasParameter(name)) throw MLException("no parameter " + assignment);
    const Value& old = par.getParameterByName(name).value();
    bool ok = true;
    if (old.isBool()) {
        ok = text == "true" || text == "false";
        par.setValue(name, BoolValue(text == "true"));
    } else if (old.isInt()) {
        par.setValue(name, IntValue(text.toInt(&ok)));
    } else if (old.isFloat()) {
        par.setValue(name, FloatValue(Scalarm(text.toDouble(&ok))));
    } else if (old.isString()) {
        par.setValue(name, StringValue(text));
    } else {
        ok = false;
    }
    if (!ok) throw MLException("parameter " + name + ": cannot use the value " + text);
}

void print_log(const GLLogStream& log) {
    for (const auto& [level, text] : log.logStringList())
        std::cout << "log: " << text.toStdString() << "\n";
}

void save_with_normals(PluginManager& pm, MeshModel& m, const QString& file, vcg::CallBackPos* cb,
                       bool everything) {
    const QString format = QFileInfo(file).suffix().toLower();
    IOPlugin* io = pm.outputMeshPlugin(format);
    if (io == nullptr) throw MLException("no plugin saves ." + format);
    RichParameterList par = io->initSaveParameter(format, m);
    int mask = vcg::tri::io::Mask::IOM_VERTNORMAL;
    if (everything) {
        using vcg::tri::io::Mask;
        for (const auto& [component, io_bit] :
             {std::pair{MeshModel::MM_VERTCOLOR, Mask::IOM_VERTCOLOR},
              {MeshModel::MM_VERTQUALITY, Mask::IOM_VERTQUALITY},
              {MeshModel::MM_VERTRADIUS, Mask::IOM_VERTRADIUS},
              {MeshModel::MM_VERTTEXCOORD, Mask::IOM_VERTTEXCOORD}})
            if (m.hasDataMask(component)) mask |= io_bit;
        // the PLY exporter offers each custom per-vertex attribute as a check box, named
        // "__CA_VS__<name>" (scalar) or "__CA_VP__<name>" (point) since 2022.02
        QStringList attributes;
        for (const RichParameter& p : par)
            if (p.name().startsWith("__CA_V") && p.value().isBool()) attributes << p.name();
        for (const QString& name : attributes) par.setValue(name, BoolValue(true));
    }
    io->save(format, file, m, mask, par, cb);
}

} // namespace hrsr::host
