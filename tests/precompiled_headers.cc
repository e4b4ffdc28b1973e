// The object of the precompiled-header target (tests/CMakeLists.txt).
