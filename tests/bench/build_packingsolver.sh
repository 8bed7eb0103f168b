#!/usr/bin/env bash
# Builds packingsolver (F. Fontan's packing solvers; https://github.com/fontanf/packingsolver) offline, for the
# side-by-side benchmark only: FabGuide does not depend on it. Its own CMake fetches Boost, HiGHS and five of its
# author's libraries from the network at configure time; this script builds the May 2024 commit (before HiGHS and
# CMake 3.28) from local clones instead, against Debian's Boost, nlohmann-json and CLP, with a CMake file of its own.
#   tests/bench/build_packingsolver.sh REPOS [BUILD]
# REPOS holds git clones named packingsolver, optimizationtools, treesearchsolver, columngenerationsolver and
# knapsacksolver (any layout `git -C REPOS/<name>` reads; default BUILD: build/packingsolver). It writes
# BUILD/bin/packingsolver_rectangle and BUILD/bin/packingsolver_rectangleguillotine.
set -euo pipefail
repos=${1:?usage: build_packingsolver.sh REPOS [BUILD]}
build=$(realpath -m "${2:-build/packingsolver}")
# The commits packingsolver 21747046 (2024-05-18) pins, directly or through columngenerationsolver.
commits=(packingsolver:21747046 optimizationtools:e96ddbe225c006911855a6c1ec31aa44fdacde2b
         treesearchsolver:7d75ba2950c6866d2fdf6d7ac145ee971ae97ce3
         columngenerationsolver:a8c5ff13ae64e6106cbc2c9eb19a3ae6023cbff5
         knapsacksolver:edd1332fa2578c2633b6f790a999d1f07ef0978c)

sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends coinor-libclp-dev \
  libboost-program-options-dev libboost-filesystem-dev libboost-thread-dev nlohmann-json3-dev cmake g++ >/dev/null

mkdir -p "$build/src"
for entry in "${commits[@]}"; do
  name=${entry%%:*} commit=${entry#*:}
  rm -rf "${build:?}/src/$name"
  mkdir -p "$build/src/$name"
  git -C "$repos/$name" archive "$commit" include src | tar -x -C "$build/src/$name"  # sources, no data
done

cat > "$build/src/CMakeLists.txt" <<'EOF'
cmake_minimum_required(VERSION 3.15)
project(PackingSolverOffline LANGUAGES CXX)
set(CMAKE_CXX_STANDARD 14)
set(CMAKE_BUILD_TYPE Release)
find_package(Boost REQUIRED COMPONENTS program_options filesystem thread)
find_package(nlohmann_json REQUIRED)
find_package(Threads REQUIRED)
find_package(PkgConfig REQUIRED)
pkg_check_modules(clp REQUIRED IMPORTED_TARGET clp)
file(GLOB knapsack knapsacksolver/src/knapsack/*.cpp knapsacksolver/src/knapsack/algorithms/*.cpp)
list(FILTER knapsack EXCLUDE REGEX "(main|generator|surrogate_relaxation)\\.cpp$")  # not in its own build
file(GLOB rectangle packingsolver/src/rectangle/*.cpp packingsolver/src/rectangleguillotine/*.cpp)
list(FILTER rectangle EXCLUDE REGEX "main\\.cpp$")
add_library(packing STATIC
  optimizationtools/src/utils/compose_stream.cpp optimizationtools/src/utils/logger.cpp
  optimizationtools/src/utils/output.cpp optimizationtools/src/utils/parameters.cpp
  optimizationtools/src/utils/timer.cpp
  treesearchsolver/src/common.cpp treesearchsolver/src/algorithm_formatter.cpp
  columngenerationsolver/src/commons.cpp columngenerationsolver/src/algorithm_formatter.cpp
  columngenerationsolver/src/algorithms/column_generation.cpp columngenerationsolver/src/algorithms/greedy.cpp
  columngenerationsolver/src/algorithms/limited_discrepancy_search.cpp
  columngenerationsolver/src/algorithms/heuristic_tree_search.cpp
  packingsolver/src/algorithms/common.cpp
  ${knapsack} ${rectangle})
target_include_directories(packing PUBLIC optimizationtools/include treesearchsolver/include
  columngenerationsolver/include knapsacksolver/include packingsolver/include)
target_compile_definitions(packing PUBLIC CLP_FOUND=1)
target_compile_options(packing PUBLIC -w)
target_link_libraries(packing PUBLIC PkgConfig::clp nlohmann_json::nlohmann_json Boost::program_options
  Boost::filesystem Boost::thread Threads::Threads)
foreach(kind rectangle rectangleguillotine)
  add_executable(packingsolver_${kind} packingsolver/src/${kind}/main.cpp)
  target_link_libraries(packingsolver_${kind} packing)
  set_target_properties(packingsolver_${kind} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/../bin)
endforeach()
EOF
cmake -S "$build/src" -B "$build/cmake" >/dev/null
cmake --build "$build/cmake" -j"$(nproc)"
ls "$build/bin"
