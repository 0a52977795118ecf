// The filter's parameters: names, labels, units, defaults (read from the core's options header),
// the HTML help built from them, and the translation back to hrsr::ReconstructionOptions.
#pragma once

#include "errors.h"
#include "ml_compat.h"
#include "options.h"

#include <QString>

namespace hrsr::plugin {

/// Adds every parameter, with its default, to `par`; `m` gives the range of the length l_min.
void add_parameters(const MeshModel& m, RichParameterList& par);

/// The options the parameters ask for (not validated: hrsr::validate names a bad one).
ReconstructionOptions read_options(const RichParameterList& par);

/// The core's complaint about an option, worded with the dialog's label of its field ("k
/// (neighbours) must be between 3 and 1000 (got 2)"); options the dialog does not show keep
/// the core's name.
QString worded(const InvalidOption& error);

/// The HTML help shown on top of the dialog: what the filter does, the papers, and every
/// parameter with its unit and default (the tooltips say more).
QString help_html();

} // namespace hrsr::plugin
