// What a run of a code was made from, so that a finished run is reused only for the same
// inputs. The stamp is a text file beside the run folder (<out>.inputs), written when the run
// has succeeded; it lists, one per line:
//   command <the shell command>
//   program <file> <fingerprint>   colza's executable, or the YADE script and the modules of
//                                  yade-scripts/ it imports
//   input <file> <fingerprint>     the config, every existing file one of its strings names
//                                  (relative to the config's folder: a packing_file), and
//                                  every existing file an argument names
//   result <summary.json> <fingerprint>   the results the stamp vouches for: summary.json,
//   result <file> <fingerprint>           then every other file of the run folder (curves,
//                                         series, the packing), in name order
// A fingerprint is FNV-1a 64 of the file's bytes (16 hex digits); paths are absolute. Two
// runs have the same inputs when every line but the last is equal: the same command on
// byte-identical configs, packings and programs. Nothing else a run reads (the system's
// libraries, YADE's installation) is stamped. colza's executable embeds its git revision
// (with -dirty for uncommitted edits), so any new build of another source tree is another
// program and its runs are made again.
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace crosscheck {

namespace fs = std::filesystem;

// The stamp of `command`, run by `programs` on `config` with `arguments` (the --set values
// and extra arguments: those that name an existing file are stamped by content). A string
// in the config names a file as given or relative to the config's folder. Throws
// std::runtime_error if the config cannot be read.
std::string run_stamp(const std::string& command, const std::vector<fs::path>& programs, const fs::path& config,
                      const std::vector<std::string>& arguments);

// <out>.inputs, the stamp file of the run folder `out`.
fs::path stamp_file(const fs::path& out);

// The inputs part of the stamp of the run in `out`; nothing if there is no stamp, or its
// summary.json line does not match out/summary.json (results written after it, e.g. by a run
// made by hand into the folder).
std::optional<std::string> read_stamp(const fs::path& out);

// When the stamp matches out/summary.json but another result it lists is missing, changed or
// unreadable (an emptied curve.csv, a kept sample that lost its packing): which and how, e.g.
// "<out>/curve.csv is missing". "" otherwise. Such a run is made again, never reused.
std::string damaged_result(const fs::path& out);

// Writes `stamp` and the result lines of the files in `out` (summary.json first) to the stamp
// file of `out` through a temporary name and a rename, so a stamp is whole or absent. Throws
// std::runtime_error if it cannot be written or summary.json cannot be read.
void write_stamp(const fs::path& out, const std::string& stamp);

// The first line of `now` that `before` lacks (what changed), for the message that says why
// a run is not reused; empty if every line of `now` is in `before`.
std::string first_change(const std::string& before, const std::string& now);

}  // namespace crosscheck
