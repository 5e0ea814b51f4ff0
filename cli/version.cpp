// The only source that reads the generated version header: a new commit compiles this file alone.
#include "version.hpp"

#include "trebuchet_version.hpp"

namespace trebuchet {

const char* build_version() { return TREBUCHET_VERSION; }
const char* build_commit() { return TREBUCHET_COMMIT; }

}  // namespace trebuchet
