// The GLSL side of the model's single-source kernels (the C++ side: core/model/glsl_compat.hpp).
// Assembled by gpu/wood_program.cpp right after "#version 330 core".
#define KERF_OUT(T) out T
#define KERF_CONST const
