// SPDX-License-Identifier: Apache-2.0
#pragma once
// The mission re-read's memory (Control-F, and a zr upload's install): the
// mission parser is init-time code (std::string, std::vector,
// std::filesystem: some 385 allocations for box_current), and the firmware
// rule is no heap after init. So the heap is not used: the arena is reserved
// once at start-up (reserve()), and while a Scope lives on a thread every
// operator new of that thread is served from it (a bump allocator; the
// block freed last is given back at once) and the arena is emptied when the
// Scope ends. A re-read that does not fit is refused (std::bad_alloc, caught
// by the reloader: "needs more than the reload arena's N bytes"), the old
// plan flown.
//
// The operator new that serves it is glider_reload_arena_new
// (reload_arena_new.cpp), linked into the programs that reserve an arena
// (glider-firmware, the heap test). Without it, or before reserve(), a Scope
// changes nothing (SIL, the tools: the heap as usual).
//
// Only what a Scope's code frees before the Scope ends may come from the
// arena: a block still live at its end (a function-local static made there
// for the first time) keeps the arena from being emptied (never overwritten);
// hence the firmware loads its mission once outside any Scope at start-up.
#include <cstddef>

namespace glider::fw::app::reload_arena {

// Init only (allocates): the arena's size. False when the memory cannot be
// had, or inside a Scope, or while blocks are live (a second call replaces
// the first arena: tests).
bool reserve(std::size_t bytes);
std::size_t capacity();
// The most a Scope has had in use at once, and the arena's use now.
std::size_t high_water();
std::size_t in_use();
// Blocks handed out and not yet freed (0 after every Scope when all is well).
std::size_t live_blocks();
// True when operator new is the arena's (glider_reload_arena_new linked).
bool serving();

// While it lives, this thread's operator new is the arena's.
class Scope {
 public:
  Scope();
  ~Scope();
  Scope(const Scope&) = delete;
  Scope& operator=(const Scope&) = delete;
  // An allocation did not fit (operator new threw std::bad_alloc).
  bool exhausted() const;
};

// For reload_arena_new.cpp only.
namespace detail {
void note_serving() noexcept;
bool in_scope();
// nullptr when it does not fit (then exhausted() is true).
void* allocate(std::size_t size, std::size_t alignment);
bool owns(const void* p);
void release(void* p);
}  // namespace detail

}  // namespace glider::fw::app::reload_arena
