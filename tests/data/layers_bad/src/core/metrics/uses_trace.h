#pragma once
#include "core/base/image.h"
#include "core/trace/raytracer.h"  // BREAKS: metrics sits below the tracer
