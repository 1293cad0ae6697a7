// Temporary translation unit until the editor lands.
#include "imgui_compat.h"
