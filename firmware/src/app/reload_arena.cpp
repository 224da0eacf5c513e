// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/app/reload_arena.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>

namespace glider::fw::app::reload_arena {
namespace {

// Each block is preceded by where it starts and ends in the arena, so the
// block freed last can be given back (a parser's temporaries mostly die in
// the order they were made).
struct Header {
  std::size_t start;  // the arena's offset before this block (header included)
  std::size_t end;    // the offset after it
};
constexpr std::size_t kHeader = 16;  // sizeof(Header), kept at the default new alignment
static_assert(sizeof(Header) <= kHeader);
constexpr std::size_t kMinAlignment = 16;  // __STDCPP_DEFAULT_NEW_ALIGNMENT__ on x86-64 and aarch64

// One arena for the process; a Scope is used by one thread at a time (the
// control loop's), the others never see it (thread_local depth).
struct Arena {
  unsigned char* base = nullptr;
  std::size_t size = 0;
  std::size_t offset = 0;
  std::size_t high_water = 0;
  std::size_t live = 0;
  bool exhausted = false;
  bool serving = false;
};
Arena g_arena;
thread_local int t_depth = 0;

std::size_t align_up(std::size_t value, std::size_t alignment) {
  return (value + alignment - 1) / alignment * alignment;
}

}  // namespace

bool reserve(std::size_t bytes) {
  if (bytes == 0 || t_depth > 0 || g_arena.live > 0) return false;
  std::free(g_arena.base);  // a second reserve (tests) replaces the first
  g_arena = Arena{.serving = g_arena.serving};
  void* memory = std::aligned_alloc(64, align_up(bytes, 64));
  if (memory == nullptr) return false;
  // Touched now, so the pages are resident (and locked with the loop's mlockall).
  std::memset(memory, 0, align_up(bytes, 64));
  g_arena.base = static_cast<unsigned char*>(memory);
  g_arena.size = bytes;
  return true;
}

std::size_t capacity() { return g_arena.size; }
std::size_t high_water() { return g_arena.high_water; }
std::size_t in_use() { return g_arena.offset; }
std::size_t live_blocks() { return g_arena.live; }
bool serving() { return g_arena.serving; }

Scope::Scope() {
  if (t_depth++ == 0) g_arena.exhausted = false;
}

Scope::~Scope() {
  // Emptied only when nothing handed out is still in use.
  if (--t_depth == 0 && g_arena.live == 0) g_arena.offset = 0;
}

bool Scope::exhausted() const { return g_arena.exhausted; }

namespace detail {

void note_serving() noexcept { g_arena.serving = true; }

bool in_scope() { return t_depth > 0 && g_arena.base != nullptr; }

void* allocate(std::size_t size, std::size_t alignment) {
  alignment = std::max(alignment, kMinAlignment);
  const std::size_t start = g_arena.offset;
  const std::size_t data = align_up(start + kHeader, alignment);
  const std::size_t end = data + std::max<std::size_t>(size, 1);
  if (end > g_arena.size || end < data) {
    g_arena.exhausted = true;
    return nullptr;
  }
  const Header header{start, end};
  std::memcpy(g_arena.base + data - kHeader, &header, sizeof header);
  g_arena.offset = end;
  g_arena.high_water = std::max(g_arena.high_water, end);
  ++g_arena.live;
  return g_arena.base + data;
}

bool owns(const void* p) {
  const auto* byte = static_cast<const unsigned char*>(p);
  return g_arena.base != nullptr && byte >= g_arena.base && byte < g_arena.base + g_arena.size;
}

void release(void* p) {
  Header header{};
  std::memcpy(&header, static_cast<unsigned char*>(p) - kHeader, sizeof header);
  if (header.end == g_arena.offset) g_arena.offset = header.start;  // the last block: given back
  if (g_arena.live > 0) --g_arena.live;
}

}  // namespace detail

}  // namespace glider::fw::app::reload_arena
