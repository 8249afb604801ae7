// The bench sheet of docs/design.md at 12 x 12 for the tune tests (tests/tune_test.cpp,
// tests/live_reference_test.cpp): 1 m, 0.2 kg, two corners pinned, falling from horizontal,
// k = 1e3 N/m per spring, xpbd at one frame a step on one thread.
#pragma once

namespace clothlab::testing {

inline constexpr const char* kTuneSheet = R"(
[cloth]
size = [1.0, 1.0]
resolution = [12, 12]
origin = [-0.5, 0.0, 0.0]
u_axis = [1, 0, 0]
v_axis = [0, 0, 1]
mass = 0.2
pins = [[0, 0], [11, 0]]
[springs]
stiffness = 1000.0
damping = 0.0
[forces]
gravity = [0, -9.81, 0]
[solver]
integrator = "xpbd"
dt = 0.016666666666666666
threads = 1
)";

}  // namespace clothlab::testing
