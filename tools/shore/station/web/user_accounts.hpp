// SPDX-License-Identifier: Apache-2.0
#pragma once
// The console's accounts: a text file, one "NAME:ROLE:HASH" a line (# comments),
// ROLE "pilot" (may act: queue, cancel, acknowledge) or "viewer" (may look).
// Written with mode 0600 by `glider-shore user add`; read at start.
#include <filesystem>
#include <map>
#include <string>

namespace glider::shore::web {

struct Account {
  std::string name, role, hash;
};

bool valid_user_name(const std::string& name);  // 1-32 of [A-Za-z0-9_.-]
bool valid_role(const std::string& role);       // pilot | viewer

// Reads the file; a malformed line is an error naming file:line (throws).
std::map<std::string, Account> read_accounts(const std::filesystem::path& file);
// Writes `text` as `file` whole, mode 0600: a hidden temporary in the same folder, fsync, rename(2)
// (a reader sees the old file or the new one, never a part). Throws naming the file.
void write_private_file(const std::filesystem::path& file, const std::string& text);
// Adds or replaces NAME (hashing the password), rewriting the file atomically with mode 0600.
void add_account(const std::filesystem::path& file, const std::string& name, const std::string& role,
                 const std::string& password);

}  // namespace glider::shore::web
