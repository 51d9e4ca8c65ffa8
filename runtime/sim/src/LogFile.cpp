#include <kse/sim/LogFile.h>

#include <fcntl.h>
#include <time.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace kse::sim {

LogFile::LogFile(const std::string& path, std::chrono::milliseconds period, std::size_t capacity)
	: path_(path), period_(period), capacity_(capacity > 0 ? capacity : 1), buffer_(new char[capacity_]),
	  last_write_(std::chrono::steady_clock::now()) {
	fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
	if (fd_ < 0) throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
}

LogFile::~LogFile() {
	Flush();
	::close(fd_);
}

bool LogFile::WriteAll(const char* data, std::size_t size) noexcept {
	while (size > 0) {
		const ssize_t written = ::write(fd_, data, size);
		if (written < 0) {
			if (errno == EINTR) continue;
			good_.store(false, std::memory_order_relaxed);
			return false;
		}
		data += written;
		size -= static_cast<std::size_t>(written);
	}
	return true;
}

void LogFile::WriteOut() {
	const std::size_t used = used_.load(std::memory_order_relaxed);
	if (used > 0) {
		writing_.store(true, std::memory_order_release);
		WriteAll(buffer_.get(), used);
		used_.store(0, std::memory_order_release);
		writing_.store(false, std::memory_order_release);
	}
	last_write_ = std::chrono::steady_clock::now();
}

void LogFile::Append(std::string_view lines) {
	std::lock_guard<std::mutex> lock(mutex_);
	if (!Good()) return;
	if (lines.size() > capacity_ - used_.load(std::memory_order_relaxed)) WriteOut();
	if (lines.size() > capacity_) {
		writing_.store(true, std::memory_order_release);
		WriteAll(lines.data(), lines.size());
		writing_.store(false, std::memory_order_release);
	} else {
		const std::size_t used = used_.load(std::memory_order_relaxed);
		std::memcpy(buffer_.get() + used, lines.data(), lines.size());
		// published only now, so that a signal handler never sees part of a line
		used_.store(used + lines.size(), std::memory_order_release);
	}
	if (std::chrono::steady_clock::now() - last_write_ >= period_) WriteOut();
}

void LogFile::Flush() {
	std::lock_guard<std::mutex> lock(mutex_);
	WriteOut();
}

void LogFile::FlushIfDue() {
	std::lock_guard<std::mutex> lock(mutex_);
	if (std::chrono::steady_clock::now() - last_write_ >= period_) WriteOut();
}

void LogFile::FlushFromSignal(const char* tail, std::size_t length) noexcept {
	// Another thread writing the buffer out finishes in a moment; waiting a little keeps its
	// lines from being written twice. (If this thread itself was writing, the wait is in vain.)
	for (int i = 0; i < 100 && writing_.load(std::memory_order_acquire); ++i) {
		const timespec pause{0, 2000000};
		::nanosleep(&pause, nullptr);
	}
	const std::size_t used = used_.load(std::memory_order_acquire);
	if (used > 0 && WriteAll(buffer_.get(), used)) used_.store(0, std::memory_order_release);
	if (tail != nullptr && length > 0) WriteAll(tail, length);
}

}  // namespace kse::sim
