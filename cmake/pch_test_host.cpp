// The target that builds cmake/precompiled.hpp with GoogleTest's header once for every
// test executable (tests/CMakeLists.txt, mmvlab_pch_test_host).
int main() { return 0; }
