# Compile-only check of the same plugin sources against the MeshLab 2022.02 plugin API (headers and
# vcglib from Debian trixie's meshlab source tarball, fetched by scripts/fetch_meshlab_2022.sh).
# Not built by default; the ctest meshlab_api_2022 builds it. It cannot be linked or run on
# bookworm: there is no 2022.02 libmeshlab-common (nor MeshLab 2022.02) to link against or load it.
set(MESHLAB_2022_SOURCE_DIR "${PROJECT_SOURCE_DIR}/.deps/meshlab-2022.02" CACHE PATH
    "MeshLab 2022.02 source tree (src/common, src/vcglib) for the compile-only API check")
if(EXISTS "${MESHLAB_2022_SOURCE_DIR}/src/common/plugins/interfaces/filter_plugin.h")
  add_library(filter_hrsr_api_2022 OBJECT EXCLUDE_FROM_ALL ${FILTER_HRSR_SOURCES})
  # hrsr_core's headers only (its sources are not recompiled), with the 2022.02 vcglib
  target_include_directories(filter_hrsr_api_2022 PRIVATE "${PROJECT_SOURCE_DIR}/vcg_ext")
  target_include_directories(filter_hrsr_api_2022 SYSTEM PRIVATE "${MESHLAB_2022_SOURCE_DIR}/src"
                                                                 "${MESHLAB_2022_SOURCE_DIR}/src/vcglib")
  target_compile_definitions(filter_hrsr_api_2022 PRIVATE MESHLAB_SCALAR=float HRSR_ML_API=2022
                                                          MESHLAB_VERSION=2022.02)
  target_link_libraries(filter_hrsr_api_2022 PRIVATE Qt5::Core Qt5::Gui Qt5::Widgets Qt5::OpenGL
                                                     Qt5::Xml GLEW::GLEW Eigen3::Eigen)
  hrsr_strict_warnings(filter_hrsr_api_2022)
  set(HRSR_API_2022_CHECK ON PARENT_SCOPE)
else()
  set(HRSR_API_2022_CHECK OFF PARENT_SCOPE)
endif()
