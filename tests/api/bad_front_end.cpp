// Not compiled: the PublicApiCheckFails test hands this file to cmake/check_public_api.cmake as
// a front-end file, which must then fail on each of its three internal includes.
#include "../../vcg_ext/rsr/observer.h"
#include "preprocess/preprocess.h"
#include "reconstruction.h"

#include <mesh/split_mesh.h>
