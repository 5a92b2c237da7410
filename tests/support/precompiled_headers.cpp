// The translation unit that builds the tests' precompiled headers (tests/CMakeLists.txt); the
// headers themselves are listed there.
