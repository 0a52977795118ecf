// Not compiled: the PublicApiCheckFails test hands this file to cmake/check_public_api.cmake as
// a front-end file, which must then fail on its internal include.
#include "preprocess/preprocess.h"
#include "reconstruction.h"
