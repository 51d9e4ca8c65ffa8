#pragma once
// A file of lines that outlives its program: the match log is streamed into it as the match runs,
// so that a crash, a hang or Ctrl+C leaves the match up to that moment, in whole lines.

#include <atomic>
#include <chrono>
#include <cstddef>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>

namespace kse::sim {

/**
 * Lines are gathered in a buffer and written whole: at least every {@code period} (checked at
 * each Append() and by whoever calls Flush() meanwhile), when the buffer is full, on Flush() and
 * at destruction. The file is never left with part of a line, so every line of it can be read
 * after the program died. Thread-safe; FlushFromSignal() is for a signal handler.
 */
class LogFile {
public:
	/** Creates or truncates the file; throws std::runtime_error when it cannot. */
	explicit LogFile(const std::string& path, std::chrono::milliseconds period = std::chrono::seconds(1),
	                 std::size_t capacity = std::size_t{1} << 20);
	~LogFile();
	LogFile(const LogFile&) = delete;
	LogFile& operator=(const LogFile&) = delete;

	/** One or more whole lines, each ending in '\n'. */
	void Append(std::string_view lines);
	/** Writes what is buffered now. */
	void Flush();
	/** Flush() when the period has passed since the last write. */
	void FlushIfDue();
	/**
	 * For a signal handler (async-signal-safe, no lock, no allocation): writes the whole lines
	 * buffered, then {@code tail} (a last whole line, or nullptr).
	 */
	void FlushFromSignal(const char* tail, std::size_t length) noexcept;

	const std::string& Path() const noexcept { return path_; }
	/** False once a write failed (disk full...); lines are then dropped. */
	bool Good() const noexcept { return good_.load(std::memory_order_relaxed); }

private:
	void WriteOut();  // under mutex_
	bool WriteAll(const char* data, std::size_t size) noexcept;

	std::string path_;
	int fd_ = -1;
	std::chrono::steady_clock::duration period_;
	std::size_t capacity_;
	std::unique_ptr<char[]> buffer_;        // fixed: a signal handler reads it
	std::atomic<std::size_t> used_{0};      // whole lines in buffer_
	std::atomic<bool> writing_{false};      // a write of buffer_ is under way
	std::atomic<bool> good_{true};
	std::mutex mutex_;
	std::chrono::steady_clock::time_point last_write_;
};

}  // namespace kse::sim
