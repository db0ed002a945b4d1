#include "core/vulkan/context.h"
#include <GLFW/glfw3.h>  // BREAKS: only the viewer knows a window
