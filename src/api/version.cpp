#include "vernacular/vernacular.hpp"

namespace vernacular {

// VERN_VERSION: project()'s version (CMakeLists.txt).
const char* version() { return VERN_VERSION; }

}  // namespace vernacular
