#pragma once
// The host's view of shaders/layout.h: the same structs, compiled as C++.
#include "layout.h"  // shaders/ is on the include path
