// Fuzz target (g): a capture file, as `npsnet check FILE.pcap` and `npsnet replay` /
// `run --replay` read it (libpcap through record::PcapReader, then every UDP payload tallied as
// DIS). libpcap reads files, so the bytes go to a file of this process in /dev/shm (or the temp
// folder) first. Not-a-capture is an expected answer (NotACapture); anything else thrown or any
// sanitizer report is a finding.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "fuzz_support.hpp"
#include "record/capture_check.hpp"
#include "record/pcap_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace npsnet;
  static const std::filesystem::path file = [] {
    const std::filesystem::path shm = "/dev/shm";
    const auto dir = std::filesystem::is_directory(shm) ? shm : std::filesystem::temp_directory_path();
    return dir / ("npsnet-fuzz-pcap-" + std::to_string(::getpid()) + ".pcap");
  }();
  if (std::FILE* f = std::fopen(file.c_str(), "wb")) {
    if (size) std::fwrite(data, 1, size, f);
    std::fclose(f);
  } else {
    return 0;
  }
  try {
    const record::CaptureReport r = record::inspect_capture(file);
    (void)r.summary(file);
  } catch (const record::NotACapture&) {
  }
  return 0;
}
