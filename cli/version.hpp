// The version and the commit a program or the Python module is built from (cli/version.cpp,
// the one source that reads the header cmake/version.cmake writes at every build).
#pragma once

namespace trebuchet {

/// The project's version, PEP 440 ("0.1.0").
const char* build_version();
/// git describe of the source it is built from ("a9948cd01234", "-dirty" when changed; "unknown"
/// outside a checkout).
const char* build_commit();

}  // namespace trebuchet
