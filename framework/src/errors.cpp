#include "pedtrack/errors.h"

namespace pedtrack {

// Key functions: they pin the vtables and type information to the framework library.
ConfigError::~ConfigError() = default;
DataError::~DataError() = default;

}  // namespace pedtrack
