#pragma once
// The scene layer knows no Vulkan.
#include "core/vulkan/context.h"  // BREAKS: core/scene includes core/base, shaders
