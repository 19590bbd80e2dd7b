// A folder a run writes its outputs into: claimed while the run's
// temporary files are there, and cleared of what runs that are over left.
//
// A run's outputs wait in temporary files beside them until all are
// written (atomic_file.hpp; interrupt_cleanup.hpp names them). While they
// are there, the run holds a lock file in the folder,
// ".vern-<pid>-<run>-XXXXXX.lock", under an open file description lock:
// the kernel (or the NFS server) keeps it while the run lives and drops it
// when the run ends, however it ends. That is how one run tells another's
// live temporaries from a dead run's, also when process ids say nothing:
// a run in another PID namespace (a container sharing the folder) or on
// another NFS client.
//
// What a run killed outright (SIGKILL, a crash, a power cut) leaves, a
// later run that writes the same output into the folder removes: a
// temporary of that name, or the backup ".old" a commit keeps, whose run
// holds no lock file there. Where that cannot be told (the file system
// has no locks, the lock file is another user's), it is removed once it
// is a day old. Temporaries of names this run does not write are left to
// the runs that write them; a dead run's lock file goes once its
// temporaries are all gone.
#pragma once

#include <filesystem>
#include <string>
#include <unordered_map>
#include <vector>

namespace vern {

class FolderClaim {
 public:
  // Claims `folder` (watched from now on: interrupt_cleanup.hpp) and lists
  // what other runs left there. Throws vern::Error (Io) naming `output`,
  // the first file to be written there, when the folder cannot be written.
  FolderClaim(const std::filesystem::path& folder, const std::filesystem::path& output);
  // Gives the claim up: the lock file is unlocked and removed.
  ~FolderClaim();
  FolderClaim(const FolderClaim&) = delete;
  FolderClaim& operator=(const FolderClaim&) = delete;

  const std::filesystem::path& folder() const { return folder_; }

  // Removes what runs that are over left for the output `name` (a file
  // name in this folder).
  void sweep(const std::string& name);

  // Puts the folder's entries (the renames into it) on disk (fsync): 0,
  // or the errno of the failure.
  int sync_folder() const;
  // Puts everything written to the folder's file system on disk (syncfs),
  // this run's files with it: 0, or the errno of the failure.
  int sync_file_system() const;

 private:
  // Whether a run still holds the folder.
  enum class Holding { NotAsked, Live, Over, Untold };
  struct Run {
    std::vector<std::string> lock_files;
    std::size_t temporaries = 0;  // of those listed, not yet removed
    Holding holding = Holding::NotAsked;
  };
  struct Leftover {
    std::string file;
    std::string run;
  };

  void list();
  void release();
  Holding holding(Run& run);
  void remove_lock_files(Run& run);

  std::filesystem::path folder_;
  int folder_fd_ = -1;
  int lock_fd_ = -1;
  std::string lock_name_;
  std::unordered_map<std::string, std::vector<Leftover>> leftovers_;  // by output name
  std::unordered_map<std::string, Run> runs_;                         // by "<pid>-<run>"
};

}  // namespace vern
