// SPDX-License-Identifier: Apache-2.0
#include "user_accounts.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fstream>
#include <stdexcept>

#include "password_hash.hpp"

namespace glider::shore::web {
namespace fs = std::filesystem;

bool valid_user_name(const std::string& name) {
  if (name.empty() || name.size() > 32) return false;
  for (char c : name) {
    const bool ok =
        (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' || c == '.';
    if (!ok) return false;
  }
  return name[0] != '.';
}

bool valid_role(const std::string& role) { return role == "pilot" || role == "viewer"; }

std::map<std::string, Account> read_accounts(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot read the users file (add one: glider-shore user add)");
  std::map<std::string, Account> accounts;
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (line.empty() || line[0] == '#') continue;
    const std::size_t a = line.find(':');
    const std::size_t b = a == std::string::npos ? a : line.find(':', a + 1);
    const std::string where = file.string() + ":" + std::to_string(number) + ": ";
    if (b == std::string::npos) throw std::runtime_error(where + "expected NAME:ROLE:HASH");
    Account account{line.substr(0, a), line.substr(a + 1, b - a - 1), line.substr(b + 1)};
    if (!valid_user_name(account.name)) {
      throw std::runtime_error(where + "user name '" + account.name + "': allowed are 1-32 of A-Z a-z 0-9 _ . -");
    }
    if (!valid_role(account.role)) {
      throw std::runtime_error(where + "role '" + account.role + "': allowed are pilot, viewer");
    }
    if (account.hash.rfind("scrypt$", 0) != 0) throw std::runtime_error(where + "hash: not a scrypt$ hash");
    accounts[account.name] = account;
  }
  return accounts;
}

void add_account(const fs::path& file, const std::string& name, const std::string& role, const std::string& password) {
  if (!valid_user_name(name))
    throw std::runtime_error("user name '" + name + "': allowed are 1-32 of A-Z a-z 0-9 _ . -");
  if (!valid_role(role)) throw std::runtime_error("role '" + role + "': allowed are pilot, viewer");
  if (password.size() < 8 || password.size() > 1024) {
    throw std::runtime_error("password: " + std::to_string(password.size()) + " characters, allowed 8-1024");
  }
  std::map<std::string, Account> accounts;
  if (fs::exists(file)) accounts = read_accounts(file);
  accounts[name] = Account{name, role, hash_password(password)};
  std::string text = "# glider-shore console users: NAME:ROLE:scrypt hash (glider-shore user add)\n";
  for (const auto& [key, account] : accounts) text += account.name + ":" + account.role + ":" + account.hash + "\n";
  write_private_file(file, text);
}

void write_private_file(const fs::path& file, const std::string& text) {
  std::string hidden = ".";  // (built in steps: GCC 12 warns falsely on "." + string here, -Wrestrict)
  hidden += file.filename().string();
  hidden += ".tmp";
  const fs::path temporary = file.parent_path() / hidden;
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
  if (fd < 0) throw std::runtime_error(temporary.string() + ": cannot write");
  const bool written = ::write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size()) && ::fsync(fd) == 0;
  ::close(fd);
  if (!written || ::rename(temporary.c_str(), file.c_str()) != 0) {
    ::unlink(temporary.c_str());
    throw std::runtime_error(file.string() + ": cannot write");
  }
}

}  // namespace glider::shore::web
