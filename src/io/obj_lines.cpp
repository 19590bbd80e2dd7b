#include "io/obj_lines.hpp"

#include <algorithm>
#include <condition_variable>
#include <cstring>
#include <deque>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "io/obj_plain_line.hpp"
#include "io/obj_reader.hpp"

namespace vern {

namespace {

// The lines of a stream, read in large blocks: each line is a view into the
// block, valid until the next call, without its line break.
class LineSplitter {
 public:
  explicit LineSplitter(std::istream& in) : in_(in), block_(kFirstBlock) {}

  // The next line; `last` when it ends the stream without a line break.
  bool next(std::string_view& line, bool& last) {
    while (true) {
      const char* begin = block_.data() + begin_;
      const std::size_t available = end_ - begin_;
      const std::size_t searched = std::min(available, kMaxObjLine + 1);
      if (const void* found = std::memchr(begin, '\n', searched)) {
        const auto length = static_cast<std::size_t>(static_cast<const char*>(found) - begin);
        return take(line, last, length, length + 1, false);
      }
      if (available > kMaxObjLine) return take(line, last, searched, searched, false);
      if (at_end_) return available != 0 && take(line, last, available, available, true);
      refill();
    }
  }

  bool failed() const { return failed_; }

 private:
  bool take(std::string_view& line, bool& last, std::size_t length, std::size_t consumed, bool at_end) {
    line = {block_.data() + begin_, length};
    last = at_end;
    begin_ += consumed;
    return true;
  }

  // Moves the unfinished line to the front and fills the rest of the
  // block. The block starts small and doubles, up to kLastBlock, while
  // reads fill it or a line does not fit: a few-kilobyte mesh (the
  // built-in primitives are ten) costs no 4 MB block, and a long line
  // (at most kMaxObjLine bytes here) always finds room.
  void refill() {
    std::memmove(block_.data(), block_.data() + begin_, end_ - begin_);
    end_ -= begin_;
    begin_ = 0;
    if ((filled_ || end_ == block_.size()) && block_.size() < kLastBlock) block_.resize(2 * block_.size());
    in_.read(block_.data() + end_, static_cast<std::streamsize>(block_.size() - end_));
    filled_ = end_ + static_cast<std::size_t>(in_.gcount()) == block_.size();
    end_ += static_cast<std::size_t>(in_.gcount());
    failed_ = in_.bad();
    at_end_ = !in_ || in_.gcount() == 0;
  }

  static constexpr std::size_t kFirstBlock = std::size_t{1} << 16;
  static constexpr std::size_t kLastBlock = 4 * kMaxObjLine;
  static_assert(kLastBlock > kMaxObjLine && kLastBlock % kFirstBlock == 0);

  std::istream& in_;
  std::vector<char> block_;
  bool filled_ = false;  // the last read filled the block: the stream goes on
  std::size_t begin_ = 0, end_ = 0;  // the unread bytes of block_
  bool at_end_ = false, failed_ = false;
};

// Lines read ahead: their bytes, and the values of the plain ones.
struct Batch {
  struct Line {
    std::size_t begin = 0, size = 0;  // in text
    bool last = false;
    PlainLine plain = PlainLine::Unread;
    std::size_t value = 0, count = 0;  // in vertices (one), or in indices
  };
  std::string text;
  std::vector<Line> lines;
  std::vector<glm::dvec3> vertices;
  std::vector<std::uint32_t> indices;
  bool end = false;     // the stream ends after these lines
  bool failed = false;  // ... because reading it failed

  void clear() {
    text.clear();
    lines.clear();
    vertices.clear();
    indices.clear();
    end = failed = false;
  }
};

// A batch is about this many bytes of text: a lock per batch, not per
// line (some ten thousand lines), and a few batches waiting at most: read
// ahead is at most a few megabytes, whatever the file.
constexpr std::size_t kBatchBytes = std::size_t{1} << 18;
constexpr std::size_t kMaxWaiting = 2;

}  // namespace

struct ObjLines::Impl {
  explicit Impl(std::istream& in) : splitter(in) {}

  LineSplitter splitter;
  bool failed = false;

  // Read-ahead: batches go from the thread to next() in order, and back.
  std::mutex mutex;
  std::condition_variable changed;
  std::deque<Batch> full;
  std::vector<Batch> spare;
  bool stopping = false;
  Batch current;           // the batch next() takes lines from
  std::size_t taken = 0;   // ... of which this many are taken
  bool started = false;    // current holds a batch from the thread
  std::jthread reader;     // last: started once the rest exists, stopped first

  void read_ahead() {
    while (true) {
      Batch b;
      {
        std::lock_guard lock(mutex);
        if (!spare.empty()) {
          b = std::move(spare.back());
          spare.pop_back();
        }
      }
      b.clear();
      b.text.reserve(kBatchBytes);  // once per batch: batches are reused
      while (b.text.size() < kBatchBytes) {
        std::string_view line;
        bool last = false;
        if (!splitter.next(line, last)) {
          b.end = true;
          b.failed = splitter.failed();
          break;
        }
        Batch::Line entry{b.text.size(), line.size(), last};
        b.text.append(line);
        // As the reader will see it: without a trailing '\r'.
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        glm::dvec3 v;
        const std::size_t first = b.indices.size();
        if (parse_plain_vertex(line, v)) {
          entry.plain = PlainLine::Vertex;
          entry.value = b.vertices.size();
          b.vertices.push_back(v);
        } else if (parse_plain_face(line, b.indices)) {
          entry.plain = PlainLine::Face;
          entry.value = first;
          entry.count = b.indices.size() - first;
        }
        b.lines.push_back(entry);
      }
      const bool end = b.end;
      {
        std::unique_lock lock(mutex);
        changed.wait(lock, [&] { return full.size() < kMaxWaiting || stopping; });
        if (stopping) return;
        full.push_back(std::move(b));
      }
      changed.notify_all();
      if (end) return;
    }
  }

  bool next_read_ahead(ObjLine& out) {
    while (!started || taken == current.lines.size()) {
      if (started && current.end) {
        failed = current.failed;
        return false;
      }
      std::unique_lock lock(mutex);
      if (started) spare.push_back(std::move(current));
      changed.wait(lock, [&] { return !full.empty(); });
      current = std::move(full.front());
      full.pop_front();
      taken = 0;
      started = true;
      lock.unlock();
      changed.notify_all();
    }
    const Batch::Line& l = current.lines[taken++];
    out.text = {current.text.data() + l.begin, l.size};
    out.last = l.last;
    out.plain = l.plain;
    if (l.plain == PlainLine::Vertex) out.vertex = current.vertices[l.value];
    out.indices = l.plain == PlainLine::Face ? current.indices.data() + l.value : nullptr;
    out.index_count = l.count;
    return true;
  }
};

ObjLines::ObjLines(std::istream& in, bool read_ahead) : impl_(std::make_unique<Impl>(in)) {
  if (read_ahead) impl_->reader = std::jthread([this] { impl_->read_ahead(); });
}

ObjLines::~ObjLines() {
  if (impl_->reader.joinable()) {
    {
      std::lock_guard lock(impl_->mutex);
      impl_->stopping = true;
    }
    impl_->changed.notify_all();
    impl_->reader.join();
  }
}

bool ObjLines::next(ObjLine& line) {
  if (impl_->reader.joinable()) return impl_->next_read_ahead(line);
  line.plain = PlainLine::Unread;
  const bool got = impl_->splitter.next(line.text, line.last);
  if (!got) impl_->failed = impl_->splitter.failed();
  return got;
}

bool ObjLines::failed() const { return impl_->failed; }

}  // namespace vern
