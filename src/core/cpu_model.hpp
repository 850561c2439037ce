// The processor this process runs on, for benchmark and result records.
#pragma once
#include <string>

namespace colza {

// The model name and, where the system gives them, x86 family and model numbers (a
// virtual machine may show only "AMD EPYC"), e.g. "AMD EPYC (family 26, model 2)", from
// /proc/cpuinfo; "unknown" where it is not readable or has no model name (e.g. aarch64).
std::string cpu_model();

}  // namespace colza
