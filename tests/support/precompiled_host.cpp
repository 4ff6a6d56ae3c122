// The translation unit that compiles the test executables' shared precompiled header
// (tests/CMakeLists.txt, gps_use_precompiled_headers); it has no code of its own.
