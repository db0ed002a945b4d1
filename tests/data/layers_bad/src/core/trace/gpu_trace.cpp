#include "core/scene/scene.h"
#include <vulkan/vulkan.h>  // BREAKS: no Vulkan in the CPU libraries
