// SPDX-License-Identifier: Apache-2.0
// The `send` listing (ZmodemTransfer::list_files) runs in the control cycle a
// send command arrives: it must not touch the heap. Every malloc, calloc,
// realloc and operator new of the process is counted around it (glibc's
// allocator is reached through its __libc_ names, so libc's own use, e.g.
// opendir's, is counted too). A plain program: exit 0 = pass.
#include <sys/stat.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <new>

#include "glider/firmware/comms/file_access_posix.hpp"
#include "glider/firmware/comms/zmodem_transfer.hpp"

extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t n, std::size_t size);
void* __libc_realloc(void* p, std::size_t size);
void __libc_free(void* p);
}

namespace {
bool counting = false;
unsigned long allocations = 0;
}  // namespace

extern "C" {
void* malloc(std::size_t size) {
  if (counting) ++allocations;
  return __libc_malloc(size);
}
void* calloc(std::size_t n, std::size_t size) {
  if (counting) ++allocations;
  return __libc_calloc(n, size);
}
void* realloc(void* p, std::size_t size) {
  if (counting) ++allocations;
  return __libc_realloc(p, size);
}
void free(void* p) { __libc_free(p); }
}

int main() {
  namespace fs = std::filesystem;
  char pattern[] = "/tmp/list_files_no_heap_XXXXXX";
  const fs::path dir = ::mkdtemp(pattern);
  for (const char* name : {"unit-2026-330-00-001.sbd", "unit-2026-330-00-000.sbd", "unit-2026-330-00-000.dbd"}) {
    std::ofstream(dir / name) << "data";
  }
  std::ofstream(dir / ".hidden") << "x";
  fs::create_directory(dir / "cac");
  glider::fw::comms::PosixFileAccess out(dir.string()), in(dir.string());
  glider::fw::comms::ZmodemTransfer transfer(dir.c_str(), out, dir.c_str(), in);
  // What a heap counter must see: the probe itself.
  counting = true;
  void* probe = std::malloc(16);
  counting = false;
  std::free(probe);
  const unsigned long probe_count = allocations;
  allocations = 0;
  counting = true;
  transfer.list_files();
  counting = false;
  const unsigned long in_listing = allocations;
  fs::remove_all(dir);
  std::printf(
      "the counter sees a malloc: %lu; allocations while listing the folder: %lu; files listed: %zu (%s, %s, %s)\n",
      probe_count, in_listing, transfer.file_count(), transfer.file_count() > 0 ? transfer.file_name(0) : "-",
      transfer.file_count() > 1 ? transfer.file_name(1) : "-", transfer.file_count() > 2 ? transfer.file_name(2) : "-");
  const bool ok = probe_count == 1 && in_listing == 0 && transfer.file_count() == 3 &&
                  std::string_view(transfer.file_name(0)) == "unit-2026-330-00-000.dbd";
  std::printf("%s\n", ok ? "PASS" : "FAIL");
  return ok ? 0 : 1;
}
