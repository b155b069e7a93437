#ifdef _WIN32
#include <windows.h>

#include <algorithm>
#include <chrono>
#include <system_error>
#include <thread>

#include "core/common/error.h"
#include "core/platform/durable_file.h"
#include "core/platform/system_error.h"

namespace lmc::platform {
namespace {

HANDLE as_handle(std::intptr_t h) {
  return reinterpret_cast<HANDLE>(h);
}

// Another program holding the file open (Excel keeps a CSV it shows open without sharing; virus
// scanners open each new file for a moment) makes Windows refuse with one of these.
bool held_by_another_program(DWORD error) {
  return error == ERROR_SHARING_VIOLATION || error == ERROR_LOCK_VIOLATION || error == ERROR_ACCESS_DENIED;
}

// A scanner lets go within a moment; a person's spreadsheet does not. Retry for about a second.
constexpr int kHeldRetries = 20;
constexpr auto kHeldRetryWait = std::chrono::milliseconds(50);

std::string held_message() {
  return "the file is open in another program (a spreadsheet, an editor or a virus scanner) or is read-only: "
         "close it there and try again; nothing was written over";
}

std::string write_error_text() {
  const DWORD error = GetLastError();
  std::string text = system_error_text(static_cast<long>(error));
  if (error == ERROR_FILE_TOO_LARGE)
    text += "; the file system's file size limit was reached (FAT32 holds 4 GB at most)";
  if (error == ERROR_DISK_FULL || error == ERROR_HANDLE_DISK_FULL)
    text += "; the disk is full: free space or record to another disk";
  return text;
}

}  // namespace

DurableFile::DurableFile(const std::filesystem::path& path, OpenMode mode) {
  DWORD access = GENERIC_WRITE;
  DWORD disposition = CREATE_ALWAYS;
  if (mode == OpenMode::append) {
    access = FILE_APPEND_DATA;
    disposition = OPEN_EXISTING;
  } else if (mode == OpenMode::append_new) {
    access = FILE_APPEND_DATA;
    disposition = CREATE_NEW;
  }
  // Others may read (a viewer following the journal) and rename or delete (a clean session close
  // removes files still open elsewhere in this program), as on Linux.
  const DWORD share = FILE_SHARE_READ | FILE_SHARE_DELETE;
  for (int attempt = 0;; ++attempt) {
    const HANDLE h = CreateFileW(path.c_str(), access, share, nullptr, disposition, FILE_ATTRIBUTE_NORMAL, nullptr);
    if (h != INVALID_HANDLE_VALUE) {
      handle_ = reinterpret_cast<std::intptr_t>(h);
      return;
    }
    const DWORD error = GetLastError();
    if (held_by_another_program(error) && attempt < kHeldRetries) {
      std::this_thread::sleep_for(kHeldRetryWait);
      continue;
    }
    throw Error(ErrorLocation{path.string()},
                held_by_another_program(error)
                    ? held_message()
                    : "cannot open for writing: " + system_error_text(static_cast<long>(error)));
  }
}

DurableFile::~DurableFile() {
  if (is_open()) CloseHandle(as_handle(handle_));
}

bool DurableFile::write(std::string_view data) {
  while (!data.empty()) {
    const DWORD chunk = static_cast<DWORD>(std::min<size_t>(data.size(), 1u << 30));
    DWORD written = 0;
    if (!WriteFile(as_handle(handle_), data.data(), chunk, &written, nullptr)) {
      error_ = write_error_text();
      return false;
    }
    data.remove_prefix(written);
    written_ += written;
  }
  return true;
}

bool DurableFile::deleted_while_open() const {
  // Deleting a file another handle holds open (allowed by FILE_SHARE_DELETE) only marks it for
  // deletion; the handle's standard information says so.
  FILE_STANDARD_INFO info{};
  return is_open() && GetFileInformationByHandleEx(as_handle(handle_), FileStandardInfo, &info, sizeof info) &&
         (info.DeletePending || info.NumberOfLinks == 0);
}

bool DurableFile::sync() {
  if (FlushFileBuffers(as_handle(handle_))) return true;
  // A console or pipe cannot be flushed; nothing is lost by that.
  if (const DWORD error = GetLastError(); error == ERROR_INVALID_HANDLE || error == ERROR_INVALID_FUNCTION) return true;
  error_ = last_system_error();
  return false;
}

bool DurableFile::close() {
  if (!is_open()) return true;
  const BOOL ok = CloseHandle(as_handle(handle_));
  handle_ = kClosed;
  if (ok) return true;
  error_ = last_system_error();
  return false;
}

void replace_file(const std::filesystem::path& from, const std::filesystem::path& to) {
  // Windows says "access denied" for a folder in the way too; that is no program's doing.
  if (std::error_code ec; std::filesystem::is_directory(to, ec))
    throw Error(ErrorLocation{to.string()}, "rename failed: a folder of that name is in the way");
  // WRITE_THROUGH: the call returns only once the move is on the disk, as rename + a synced
  // folder would be on Linux.
  for (int attempt = 0;; ++attempt) {
    if (MoveFileExW(from.c_str(), to.c_str(), MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH)) return;
    const DWORD error = GetLastError();
    if (held_by_another_program(error) && attempt < kHeldRetries) {
      std::this_thread::sleep_for(kHeldRetryWait);
      continue;
    }
    throw Error(ErrorLocation{to.string()}, held_by_another_program(error)
                                                ? held_message()
                                                : "rename failed: " + system_error_text(static_cast<long>(error)));
  }
}

}  // namespace lmc::platform
#endif
