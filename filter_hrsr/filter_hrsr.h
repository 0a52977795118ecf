// MeshLab filter "Surface Reconstruction: HRsR": a thin adapter between MeshLab's layers and
// parameters and hrsr::reconstruct (vcg_ext/). It translates, reports progress, logs; nothing else.
#pragma once

#include "ml_compat.h"
#include "reconstruction.h"

#include <QObject>

class FilterHrsrPlugin : public QObject, public MLFilterBase {
    Q_OBJECT
#if HRSR_ML_API >= 2022
    MESHLAB_PLUGIN_IID_EXPORTER(FILTER_PLUGIN_IID)
    Q_INTERFACES(FilterPlugin)
#else
    MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
    Q_INTERFACES(MeshFilterInterface)
#endif

public:
    enum { FP_HRSR };

    FilterHrsrPlugin();
    QString pluginName() const override;
    QString filterName(int filter) const override;
    QString filterInfo(int filter) const override;

#if HRSR_ML_API >= 2022
    FilterClass getClass(const QAction*) const override;
    FilterArity filterArity(const QAction*) const override {
        return SINGLE_MESH;
    }
    int getPreConditions(const QAction*) const override;
    int getRequirements(const QAction*) override;
    int postCondition(const QAction*) const override;
    RichParameterList initParameterList(const QAction*, const MeshModel& m) override;
    std::map<std::string, QVariant> applyFilter(const QAction* action, const RichParameterList& par,
                                                MeshDocument& md, unsigned int& postConditionMask,
                                                vcg::CallBackPos* cb) override;
    QString pythonFilterName(ActionIDType) const override;
#else
    FilterClass getClass(QAction*) override;
    FILTER_ARITY filterArity(QAction*) const override {
        return SINGLE_MESH;
    }
    int getPreConditions(QAction*) const override;
    int getRequirements(QAction*) override;
    int postCondition(QAction*) const override;
    void initParameterSet(QAction*, MeshModel& m, RichParameterList& par) override;
    bool applyFilter(QAction* action, MeshDocument& md, const RichParameterList& par,
                     vcg::CallBackPos* cb) override;
#endif

private:
    void fill_parameters(const MeshModel& m, RichParameterList& par) const;
    /// Runs the reconstruction; throws std::exception subclasses with a message for the user.
    void run(MeshDocument& md, const RichParameterList& par, vcg::CallBackPos* cb);
    /// The report summary, last in the log.
    void log_summary(const hrsr::ReconstructionReport& report, double seconds);
    template <typename... Ts>
    void log_message(const char* format, Ts&&... args) {
#if HRSR_ML_API >= 2022
        log(format, std::forward<Ts>(args)...);
#else
        Log(format, std::forward<Ts>(args)...);
#endif
    }
};
