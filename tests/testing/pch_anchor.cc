// Empty on purpose: locator_test_pch exists to precompile the test headers
// (cmake/LocatorPch.cmake) that every test outside tests/core reuses, and a
// target needs one source to build its precompiled header.
