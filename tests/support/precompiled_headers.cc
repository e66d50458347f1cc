// The source of the object library hil_test_pch (tests/CMakeLists.txt): it holds nothing of its
// own; the library exists to compile the test programs' precompiled header once, which every
// hil_add_test program then reuses (target_precompile_headers REUSE_FROM hil_test_pch).
