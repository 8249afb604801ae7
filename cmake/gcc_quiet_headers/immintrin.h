// GCC 12's own immintrin.h, with its false "may be used uninitialized" warnings silenced for this
// header alone. Its _mm*_undefined_* intrinsics initialise a variable from itself (__m512d __Y =
// __Y), which GCC 12 reports wherever Eigen's AVX-512 packet code inlines them (GCC bug 105593,
// fixed in GCC 13 by the same pragmas in the header itself). CMakeLists.txt puts this folder on
// the system include path for GCC only; #include_next reads the compiler's header.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
#include_next <immintrin.h>
#pragma GCC diagnostic pop
