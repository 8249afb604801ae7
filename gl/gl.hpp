// The one include for OpenGL in vis/: glad's GL 4.5 core loader (generated at build time).
#pragma once

#include <glad/gl.h>
