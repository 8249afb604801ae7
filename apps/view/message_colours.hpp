// The colours the window's panels give warnings and errors.
#pragma once

#include <imgui.h>

namespace clothlab::vis {

inline const ImVec4 kWarningColour{1.0f, 0.8f, 0.3f, 1.0f};
inline const ImVec4 kErrorColour{1.0f, 0.45f, 0.4f, 1.0f};

}  // namespace clothlab::vis
