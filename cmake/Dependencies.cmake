# Every dependency comes from a Debian package (see README.md); nothing is downloaded at build time.
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(nlohmann_json 3.11 REQUIRED)
find_package(spdlog 1.10 REQUIRED)
find_package(Threads REQUIRED)
find_package(PkgConfig REQUIRED)
# libcpp-httplib-dev ships a compiled library with a pkg-config file only. Its cflags carry the
# OpenSSL/zlib/brotli defines the library was built with; our code must see the same class layout.
# Only the tests and benchmarks use it, as their HTTP client: the service depends on none of it.
pkg_check_modules(CPPHTTPLIB REQUIRED IMPORTED_TARGET cpp-httplib)
