// The target that builds cmake/precompiled.hpp once for every library layer that reuses
// it (CMakeLists.txt, mmvlab_pch_host); it holds no code of its own.
