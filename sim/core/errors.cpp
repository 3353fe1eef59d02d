#include "sim/core/errors.hpp"

namespace mmv::detail {

void throwInternal(const char* condition, const char* file, int line) {
  throw InternalError(std::string("internal error: ") + condition + " failed at " + file + ":" + std::to_string(line) +
                      " (please report it with the scene and command)");
}

}  // namespace mmv::detail
