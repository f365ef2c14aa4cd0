#include "tendril/core/numerics_mode.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string_view>
#include <utility>

#include "tendril/core/error.hpp"

namespace tendril {
namespace {

// The kernel choices a portable build pins: AVX2 paths, which every x86-64-v3 CPU runs.
constexpr std::array<std::pair<const char*, const char*>, 4> kPinnedKernels{{
    {"OPENBLAS_CORETYPE", "Haswell"},  // OpenBLAS's GEMM and vector kernels
    {"ATEN_CPU_CAPABILITY", "avx2"},   // LibTorch's vectorised operators
    {"ONEDNN_MAX_CPU_ISA", "AVX2"},    // oneDNN, under LibTorch's convolutions and RNNs
    {"DNNL_MAX_CPU_ISA", "AVX2"},      // the same, by its older name
}};

bool pinned_in_environment() {
  for (const auto& [name, value] : kPinnedKernels) {
    const char* current = std::getenv(name);
    if (current == nullptr || std::string_view(current) != value) return false;
  }
  return true;
}

NumericsMode detect() {
  NumericsMode mode;
#if defined(TENDRIL_PORTABLE_BUILD)
  mode.portable = true;
  mode.compiled_for = "x86-64-v3";
  mode.kernels_pinned = pinned_in_environment();
#elif defined(TENDRIL_NATIVE_BUILD)
  mode.compiled_for = "-march=native";
#else
  mode.compiled_for = "the compiler's default target";
#endif
  return mode;
}

// OpenBLAS's name for the kernels it chose ("Cooperlake", "Haswell", ...), or "" when no
// OpenBLAS is in reach.
std::string openblas_core_name() {
  void* library = dlopen("libopenblas.so.0", RTLD_LAZY | RTLD_LOCAL);
  if (library == nullptr) return "";
  using CoreName = char* (*)();
  auto core_name = reinterpret_cast<CoreName>(dlsym(library, "openblas_get_corename"));
  std::string name = core_name != nullptr ? std::string(core_name()) : "";
  dlclose(library);
  return name;
}

std::string cpu_model() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line)) {
    if (line.rfind("model name", 0) == 0) {
      const std::size_t colon = line.find(':');
      if (colon != std::string::npos) return line.substr(line.find_first_not_of(' ', colon + 1));
    }
  }
  return "unknown";
}

// A YAML double-quoted scalar.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

}  // namespace

std::string tendril_version() { return TENDRIL_VERSION; }

std::string machine_record() {
  return "tendril: " + quoted(tendril_version()) + "\nnumerics: " + quoted(numerics_description()) +
         "\ncpu: " + quoted(cpu_model()) + "\n";
}

const NumericsMode& numerics_mode() {
  static const NumericsMode mode = detect();
  return mode;
}

void pin_portable_kernels(char** argv) {
  if (!numerics_mode().portable || pinned_in_environment()) return;
  for (const auto& [name, value] : kPinnedKernels) setenv(name, value, 1);
  execv("/proc/self/exe", argv);
  throw Error(
      std::string("cannot restart the program with pinned kernels: ") + std::strerror(errno),
      "portable build");
}

std::string portable_kernel_variables() {
  std::string text;
  for (const auto& [name, value] : kPinnedKernels) {
    if (!text.empty()) text += ' ';
    text += std::string(name) + "=" + value;
  }
  return text;
}

std::string numerics_description() {
  const NumericsMode& mode = numerics_mode();
  std::string text;
  if (mode.portable) {
    text = std::string("portable build (x86-64-v3, ") +
           (mode.kernels_pinned ? "kernels pinned)" : "kernels NOT pinned)");
  } else {
    text = (mode.compiled_for == "-march=native" ? "native build (" : "generic build (") +
           mode.compiled_for + ")";
  }
  const std::string core = openblas_core_name();
  if (!core.empty()) text += "; OpenBLAS kernels " + core;
  return text;
}

}  // namespace tendril
