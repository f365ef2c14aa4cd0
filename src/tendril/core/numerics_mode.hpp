#pragma once

#include <string>

namespace tendril {

// Which floating-point results a program can reproduce (docs/reproducibility.md).
//
// A native build (the default, -march=native) runs code compiled for the build machine's CPU and
// lets OpenBLAS, LibTorch and oneDNN pick their kernels for the CPU they run on: reruns with the
// same config and seed are bit-identical on one machine, not across machines. A portable build
// (CMake -DTENDRIL_PORTABLE=ON) compiles for x86-64-v3 (AVX2 and FMA, every x86-64 CPU since
// 2013–2017) and pins those libraries' kernels to the same AVX2 paths on every CPU, so results
// are bit-identical on every x86-64-v3 machine with the same build and libraries.
struct NumericsMode {
  bool portable = false;
  std::string compiled_for;  // "-march=native", "x86-64-v3", or the compiler's default target
  // Whether this process runs with the pinned kernels (always false in a native build).
  bool kernels_pinned = false;
};

const NumericsMode& numerics_mode();

// In a portable build whose process does not yet run with the pinned kernels, sets the variables
// that pin them (OPENBLAS_CORETYPE=Haswell, ATEN_CPU_CAPABILITY=avx2, ONEDNN_MAX_CPU_ISA=AVX2)
// and executes the program again with the same arguments; the libraries read them only when they
// are loaded, before main. A variable the user already set to another value is overridden (the
// mode promises these kernels). Returns in every other case, and in the re-executed process.
// `argv` as main received it.
void pin_portable_kernels(char** argv);

// The variables pin_portable_kernels sets, "NAME=value" each, for a program that cannot re-execute
// itself (the Python module reports them when they are missing).
std::string portable_kernel_variables();

// tendril's version (CMake's project version: the one source of it).
std::string tendril_version();

// What a run directory records of the machine that made it (machine.yaml): tendril's version,
// the numerics description, the CPU model. YAML text.
std::string machine_record();

// One line for `--version`, run directories and results pages: the build mode and the kernels
// in use, e.g. "native build (-march=native); OpenBLAS kernels Cooperlake".
std::string numerics_description();

}  // namespace tendril
