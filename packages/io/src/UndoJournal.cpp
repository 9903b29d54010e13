// The undo journal of snapshot appends (UndoJournal.hpp). (Length: the HDF5 file driver's
// callbacks, the journal they write and its replay are kept together: a change to one must
// be checked against the others.)
#include "UndoJournal.hpp"

#include "capsula/core/Error.hpp"

#include <H5FDpublic.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <utility>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace capsula::io::hdf5 {

namespace {

constexpr char kMagic[8] = {'C', 'A', 'P', 'U', 'N', 'D', 'O', '1'};
constexpr std::size_t kHeaderSize = 16;

std::uint64_t fnv1a(std::uint64_t hash, const void* data, std::size_t size)
{
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) {
    hash = (hash ^ bytes[i]) * 1099511628211ULL;
  }
  return hash;
}

std::uint64_t recordChecksum(std::uint64_t offset, std::uint64_t length, const unsigned char* bytes)
{
  std::uint64_t hash = 14695981039346656037ULL;
  hash = fnv1a(hash, &offset, sizeof(offset));
  hash = fnv1a(hash, &length, sizeof(length));
  return fnv1a(hash, bytes, static_cast<std::size_t>(length));
}

bool writeAll(int fd, const void* data, std::size_t size, off_t offset)
{
  const auto* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::pwrite(fd, p, size, offset);
    if (n < 0 && errno == EINTR) {
      continue;
    }
    if (n <= 0) {
      return false;
    }
    p += n;
    size -= static_cast<std::size_t>(n);
    offset += n;
  }
  return true;
}

/// Reads what there is (zeros past the end of the file).
bool readAll(int fd, void* data, std::size_t size, off_t offset)
{
  auto* p = static_cast<char*>(data);
  while (size > 0) {
    const ssize_t n = ::pread(fd, p, size, offset);
    if (n < 0 && errno == EINTR) {
      continue;
    }
    if (n < 0) {
      return false;
    }
    if (n == 0) {
      std::memset(p, 0, size);
      return true;
    }
    p += n;
    size -= static_cast<std::size_t>(n);
    offset += n;
  }
  return true;
}

/// Makes the creation or removal of a file in `directory` durable.
void syncDirectoryOf(const std::string& path)
{
  const std::string directory = std::filesystem::path(path).parent_path().string();
  const int fd = ::open(directory.empty() ? "." : directory.c_str(), O_RDONLY | O_DIRECTORY);
  if (fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
}

// ---- the driver -------------------------------------------------------------------------

struct JournalState {
  std::string path;
  std::string journalPath;
  int journalFd = -1;
  haddr_t protectedEnd = 0;                       // the file's size at open: bytes below it are journalled
  std::vector<std::pair<haddr_t, haddr_t>> saved; // [begin, end) already journalled, sorted
  // Writes into [0, protectedEnd) held back until commit(): one journal sync covers them all.
  struct PendingWrite {
    haddr_t address;
    std::vector<unsigned char> bytes;
  };
  std::vector<PendingWrite> pending;
};

/// HDF5 hands the driver its own H5FD_t back: it must come first.
struct JournalFile {
  H5FD_t pub;
  int fd;
  haddr_t eoa;
  haddr_t eof;
  dev_t device;
  ino_t inode;
  JournalState* state;
};

JournalFile* self(H5FD_t* file)
{
  return reinterpret_cast<JournalFile*>(file);
}

const JournalFile* self(const H5FD_t* file)
{
  return reinterpret_cast<const JournalFile*>(file);
}

bool openJournal(JournalState& s)
{
  s.journalFd = ::open(s.journalPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (s.journalFd < 0) {
    return false;
  }
  unsigned char header[kHeaderSize];
  std::memcpy(header, kMagic, 8);
  const std::uint64_t end = s.protectedEnd;
  std::memcpy(header + 8, &end, 8);
  if (!writeAll(s.journalFd, header, kHeaderSize, 0)) {
    return false;
  }
  syncDirectoryOf(s.journalPath); // the journal's name is durable; its content is synced by commit()
  return true;
}

/// Appends to the journal the old bytes of [begin, end) not saved yet (not synced).
bool saveOriginals(JournalFile& f, haddr_t begin, haddr_t end)
{
  JournalState& s = *f.state;
  end = std::min(end, s.protectedEnd);
  if (begin >= end) {
    return true;
  }
  // The parts of [begin, end) outside the saved intervals.
  std::vector<std::pair<haddr_t, haddr_t>> missing;
  haddr_t cursor = begin;
  for (const auto& [b, e] : s.saved) {
    if (e <= cursor) {
      continue;
    }
    if (b >= end) {
      break;
    }
    if (b > cursor) {
      missing.emplace_back(cursor, b);
    }
    cursor = std::max(cursor, e);
    if (cursor >= end) {
      break;
    }
  }
  if (cursor < end) {
    missing.emplace_back(cursor, end);
  }
  if (missing.empty()) {
    return true;
  }
  if (s.journalFd < 0 && !openJournal(s)) {
    return false;
  }
  off_t at = ::lseek(s.journalFd, 0, SEEK_END);
  for (const auto& [b, e] : missing) {
    const std::uint64_t offset = b, length = e - b;
    unsigned char head[16];
    std::memcpy(head, &offset, 8);
    std::memcpy(head + 8, &length, 8);
    std::vector<unsigned char> bytes(static_cast<std::size_t>(length));
    if (!readAll(f.fd, bytes.data(), bytes.size(), static_cast<off_t>(offset))) {
      return false;
    }
    const std::uint64_t checksum = recordChecksum(offset, length, bytes.data());
    if (!writeAll(s.journalFd, head, sizeof(head), at) || !writeAll(s.journalFd, bytes.data(), bytes.size(), at + 16) ||
        !writeAll(s.journalFd, &checksum, sizeof(checksum), at + 16 + static_cast<off_t>(length))) {
      return false;
    }
    at += static_cast<off_t>(24 + length);
    s.saved.emplace_back(b, e);
  }
  std::sort(s.saved.begin(), s.saved.end());
  return true;
}

/// Journals the originals of every held-back write, syncs the journal once, then writes.
bool commit(JournalFile& f)
{
  JournalState& s = *f.state;
  if (s.pending.empty()) {
    return true;
  }
  for (const auto& w : s.pending) {
    if (!saveOriginals(f, w.address, w.address + w.bytes.size())) {
      return false;
    }
  }
  if (s.journalFd < 0 || ::fdatasync(s.journalFd) != 0) {
    return false;
  }
  for (const auto& w : s.pending) {
    if (!writeAll(f.fd, w.bytes.data(), w.bytes.size(), static_cast<off_t>(w.address))) {
      return false;
    }
  }
  s.pending.clear();
  return true;
}

H5FD_t* driverOpen(const char* name, unsigned flags, hid_t, haddr_t maxaddr)
{
  if (name == nullptr || maxaddr == 0 || maxaddr == HADDR_UNDEF) {
    return nullptr;
  }
  int mode = (flags & H5F_ACC_RDWR) ? O_RDWR : O_RDONLY;
  if (flags & H5F_ACC_TRUNC) {
    mode |= O_TRUNC;
  }
  if (flags & H5F_ACC_CREAT) {
    mode |= O_CREAT;
  }
  if (flags & H5F_ACC_EXCL) {
    mode |= O_EXCL;
  }
  const int fd = ::open(name, mode, 0644);
  if (fd < 0) {
    return nullptr;
  }
  struct stat info {};
  if (::fstat(fd, &info) != 0) {
    ::close(fd);
    return nullptr;
  }
  auto* f = new JournalFile{};
  f->fd = fd;
  f->eoa = 0;
  f->eof = static_cast<haddr_t>(info.st_size);
  f->device = info.st_dev;
  f->inode = info.st_ino;
  f->state = new JournalState{};
  f->state->path = name;
  f->state->journalPath = undoJournalPathFor(name);
  f->state->protectedEnd = static_cast<haddr_t>(info.st_size);
  return &f->pub;
}

herr_t driverClose(H5FD_t* file)
{
  JournalFile* f = self(file);
  bool ok = commit(*f);
  if (ok && f->state->journalFd >= 0) {
    // The file must be complete on disk before its undo information goes.
    ok = ::fsync(f->fd) == 0;
    ::close(f->state->journalFd);
    if (ok) {
      ok = ::unlink(f->state->journalPath.c_str()) == 0;
      syncDirectoryOf(f->state->journalPath);
    }
  }
  ok = ::close(f->fd) == 0 && ok;
  delete f->state;
  delete f;
  return ok ? 0 : -1;
}

int driverCompare(const H5FD_t* a, const H5FD_t* b)
{
  const JournalFile *x = self(a), *y = self(b);
  if (x->device != y->device) {
    return x->device < y->device ? -1 : 1;
  }
  if (x->inode != y->inode) {
    return x->inode < y->inode ? -1 : 1;
  }
  return 0;
}

herr_t driverQuery(const H5FD_t*, unsigned long* flags)
{
  if (flags != nullptr) {
    *flags = H5FD_FEAT_AGGREGATE_METADATA | H5FD_FEAT_ACCUMULATE_METADATA | H5FD_FEAT_DATA_SIEVE |
             H5FD_FEAT_AGGREGATE_SMALLDATA | H5FD_FEAT_POSIX_COMPAT_HANDLE | H5FD_FEAT_DEFAULT_VFD_COMPATIBLE;
  }
  return 0;
}

haddr_t driverGetEoa(const H5FD_t* file, H5FD_mem_t)
{
  return self(file)->eoa;
}

herr_t driverSetEoa(H5FD_t* file, H5FD_mem_t, haddr_t address)
{
  self(file)->eoa = address;
  return 0;
}

haddr_t driverGetEof(const H5FD_t* file, H5FD_mem_t)
{
  return self(file)->eof;
}

herr_t driverGetHandle(H5FD_t* file, hid_t, void** handle)
{
  if (handle == nullptr) {
    return -1;
  }
  *handle = &self(file)->fd;
  return 0;
}

herr_t driverRead(H5FD_t* file, H5FD_mem_t, hid_t, haddr_t address, size_t size, void* buffer)
{
  JournalFile* f = self(file);
  if (address == HADDR_UNDEF || address + size > f->eoa) {
    return -1;
  }
  if (!readAll(f->fd, buffer, size, static_cast<off_t>(address))) {
    return -1;
  }
  // What the file will hold once the held-back writes are done (later ones win).
  auto* out = static_cast<unsigned char*>(buffer);
  for (const auto& w : f->state->pending) {
    const haddr_t begin = std::max(address, w.address);
    const haddr_t end =
        std::min(static_cast<haddr_t>(address + size), static_cast<haddr_t>(w.address + w.bytes.size()));
    if (begin < end) {
      std::memcpy(out + (begin - address), w.bytes.data() + (begin - w.address), static_cast<std::size_t>(end - begin));
    }
  }
  return 0;
}

herr_t driverWrite(H5FD_t* file, H5FD_mem_t, hid_t, haddr_t address, size_t size, const void* buffer)
{
  JournalFile* f = self(file);
  if (address == HADDR_UNDEF || address + size > f->eoa) {
    return -1;
  }
  // Bytes that existed at open wait for commit(); new bytes go straight to the file.
  const haddr_t end = address + size;
  const haddr_t split = std::clamp(f->state->protectedEnd, address, end);
  const auto* bytes = static_cast<const unsigned char*>(buffer);
  if (split > address) {
    f->state->pending.push_back({address, std::vector<unsigned char>(bytes, bytes + (split - address))});
  }
  if (end > split &&
      !writeAll(f->fd, bytes + (split - address), static_cast<std::size_t>(end - split), static_cast<off_t>(split))) {
    return -1;
  }
  f->eof = std::max(f->eof, static_cast<haddr_t>(address + size));
  return 0;
}

herr_t driverTruncate(H5FD_t* file, hid_t, hbool_t)
{
  JournalFile* f = self(file);
  if (!commit(*f)) {
    return -1;
  }
  if (f->eoa != f->eof) {
    // Cutting bytes that existed at open (space HDF5 freed at the end) changes them too.
    if (f->eoa < f->state->protectedEnd &&
        (!saveOriginals(*f, f->eoa, f->eof) || f->state->journalFd < 0 || ::fdatasync(f->state->journalFd) != 0)) {
      return -1;
    }
    if (::ftruncate(f->fd, static_cast<off_t>(f->eoa)) != 0) {
      return -1;
    }
    f->eof = f->eoa;
  }
  return 0;
}

herr_t driverFlush(H5FD_t* file, hid_t, hbool_t)
{
  return commit(*self(file)) ? 0 : -1;
}

hid_t driverId()
{
  static const H5FD_class_t driverClass = [] {
    H5FD_class_t c{};
    c.name = "capsula_undo_journal";
    c.maxaddr = static_cast<haddr_t>((static_cast<std::uint64_t>(1) << 63) - 1);
    c.fc_degree = H5F_CLOSE_WEAK;
    c.open = driverOpen;
    c.close = driverClose;
    c.cmp = driverCompare;
    c.query = driverQuery;
    c.get_eoa = driverGetEoa;
    c.set_eoa = driverSetEoa;
    c.get_eof = driverGetEof;
    c.get_handle = driverGetHandle;
    c.read = driverRead;
    c.write = driverWrite;
    c.flush = driverFlush;
    c.truncate = driverTruncate;
    const H5FD_mem_t map[H5FD_MEM_NTYPES] = H5FD_FLMAP_DICHOTOMY;
    std::copy(std::begin(map), std::end(map), std::begin(c.fl_map));
    return c;
  }();
  static hid_t id = H5I_INVALID_HID;
  if (id < 0 || H5Iis_valid(id) <= 0) {
    id = H5FDregister(&driverClass);
  }
  return id;
}

} // namespace

std::string undoJournalPathFor(const std::string& path)
{
  return path + ".undo";
}

Handle openFileWithUndoJournal(const std::string& path, const std::string& role)
{
  ErrorSilencer quiet;
  if (!std::filesystem::exists(path)) {
    throw core::IoError("The " + role + " file '" + path + "' does not exist.");
  }
  if (H5Fis_hdf5(path.c_str()) <= 0) {
    throw core::IoError("The " + role + " file '" + path + "' is not a readable HDF5 file (truncated or corrupt?).");
  }
  const hid_t driver = driverId();
  Handle fapl(H5Pcreate(H5P_FILE_ACCESS));
  if (driver < 0 || fapl.get() < 0 || H5Pset_driver(fapl.get(), driver, nullptr) < 0) {
    throw core::IoError("Cannot set up the journalling HDF5 driver for '" + path + "'.");
  }
  Handle file(H5Fopen(path.c_str(), H5F_ACC_RDWR, fapl.get()));
  if (file.get() < 0) {
    throw core::IoError("The " + role + " file '" + path +
                        "' cannot be opened for writing (read-only, open elsewhere, or corrupt).");
  }
  return file;
}

bool undoInterruptedWrite(const std::string& path)
{
  const std::string journalPath = undoJournalPathFor(path);
  if (!std::filesystem::exists(journalPath)) {
    return false;
  }
  std::ifstream in(journalPath, std::ios::binary);
  const std::vector<unsigned char> text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (text.size() >= kHeaderSize && std::memcmp(text.data(), kMagic, 8) == 0) {
    std::uint64_t protectedEnd = 0;
    std::memcpy(&protectedEnd, text.data() + 8, 8);
    const int fd = ::open(path.c_str(), O_WRONLY);
    if (fd < 0) {
      throw core::IoError("Cannot open '" + path + "' to undo an interrupted write: " + std::strerror(errno) + ".");
    }
    bool ok = true;
    std::size_t at = kHeaderSize;
    while (ok && at + 24 <= text.size()) {
      std::uint64_t offset = 0, length = 0, checksum = 0;
      std::memcpy(&offset, text.data() + at, 8);
      std::memcpy(&length, text.data() + at + 8, 8);
      if (length > text.size() - at - 24) {
        break; // cut short: the write it protects never happened
      }
      const unsigned char* bytes = text.data() + at + 16;
      std::memcpy(&checksum, bytes + length, 8);
      if (checksum != recordChecksum(offset, length, bytes)) {
        break;
      }
      ok = writeAll(fd, bytes, static_cast<std::size_t>(length), static_cast<off_t>(offset));
      at += 24 + static_cast<std::size_t>(length);
    }
    ok = ok && ::ftruncate(fd, static_cast<off_t>(protectedEnd)) == 0 && ::fsync(fd) == 0;
    ::close(fd);
    if (!ok) {
      throw core::IoError("Cannot undo the interrupted write of '" + path + "' (journal '" + journalPath +
                          "'): " + std::strerror(errno) + ".");
    }
  }
  // A journal without a complete header was created before any byte of the file changed.
  discardUndoJournal(path);
  return true;
}

void discardUndoJournal(const std::string& path)
{
  const std::string journalPath = undoJournalPathFor(path);
  std::error_code ec;
  std::filesystem::remove(journalPath, ec);
  if (ec) {
    throw core::IoError("Cannot remove the journal '" + journalPath + "': " + ec.message() + ".");
  }
  syncDirectoryOf(journalPath);
}

} // namespace capsula::io::hdf5
