#pragma once
// "physltl-studio 0.1.0 (git <describe>)": the version and commit this program was built from
// (cmake/build_version.cmake). Campaign manifests record it; `--version` prints it.

namespace physltl::common {

const char* build_version();

}  // namespace physltl::common
