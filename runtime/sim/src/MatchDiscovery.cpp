#include <kse/sim/MatchDiscovery.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include <kse/robot/MonitorServer.h>
#include <kse/sim/Match.h>
#include <kse/sim/MatchLog.h>

namespace kse::sim {

namespace {

std::string Failure(const std::string& what, const std::string& path) {
	return "cannot " + what + " " + path + ": " + std::strerror(errno);
}

/** Makes {@code path} a folder only this user may enter (0700), refusing one that belongs to somebody else or is a link. */
void PrivateFolder(const std::string& path) {
	if (::mkdir(path.c_str(), 0700) != 0 && errno != EEXIST) throw std::runtime_error(Failure("make the folder", path));
	struct stat status {};
	if (::lstat(path.c_str(), &status) != 0) throw std::runtime_error(Failure("read the folder", path));
	if (!S_ISDIR(status.st_mode)) throw std::runtime_error(path + " is not a folder (a link or a file): the match is not announced there");
	if (status.st_uid != ::geteuid()) throw std::runtime_error(path + " belongs to another user: the match is not announced there");
	// an older folder made with a looser umask: the announcements hold monitor keys
	if ((status.st_mode & 0077) != 0 && ::chmod(path.c_str(), 0700) != 0) throw std::runtime_error(Failure("make private the folder", path));
}

}  // namespace

std::string DiscoveryFolder() {
	const char* runtime = std::getenv("XDG_RUNTIME_DIR");
	if (runtime != nullptr && runtime[0] == '/') return std::string(runtime) + "/kse/matches";
	const char* home = std::getenv("HOME");
	if (home != nullptr && home[0] == '/') return std::string(home) + "/.cache/kse/matches";
	return {};
}

std::string AnnouncementJson(const Match& match, long pid, std::uint16_t port, const std::string& token, double started_ms) {
	std::string json = "{\"pid\":" + std::to_string(pid) + ",\"port\":" + std::to_string(port) + ",\"token\":";
	robot::AppendJsonString(json, token);
	json += ",\"started\":" + Fixed(started_ms, 0) + "," + MatchRecordFields(match) + "}\n";
	return json;
}

MatchAnnouncement::MatchAnnouncement(const std::string& folder, const std::string& json) {
	if (folder.empty()) throw std::runtime_error("neither XDG_RUNTIME_DIR nor HOME is set: the match is not announced");
	// the parents ("kse", and ".cache" under HOME) are made as needed; only the last two are ours to narrow
	const std::string parent = folder.substr(0, folder.rfind('/'));
	const std::string grandparent = parent.substr(0, parent.rfind('/'));
	if (::mkdir(grandparent.c_str(), 0700) != 0 && errno != EEXIST) throw std::runtime_error(Failure("make the folder", grandparent));
	PrivateFolder(parent);
	PrivateFolder(folder);
	const std::string name = std::to_string(::getpid()) + ".json";
	path_ = folder + "/" + name;
	// a dot name readers skip, then renamed: a reader sees the whole file or none
	const std::string temporary = folder + "/." + name + ".tmp";
	::unlink(temporary.c_str());
	const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0600);
	if (fd < 0) throw std::runtime_error(Failure("write", temporary));
	std::size_t written = 0;
	while (written < json.size()) {
		const ssize_t n = ::write(fd, json.data() + written, json.size() - written);
		if (n < 0 && errno == EINTR) continue;
		if (n <= 0) {
			const std::string message = Failure("write", temporary);
			::close(fd);
			::unlink(temporary.c_str());
			throw std::runtime_error(message);
		}
		written += static_cast<std::size_t>(n);
	}
	::close(fd);
	if (::rename(temporary.c_str(), path_.c_str()) != 0) {
		const std::string message = Failure("write", path_);
		::unlink(temporary.c_str());
		throw std::runtime_error(message);
	}
}

MatchAnnouncement::~MatchAnnouncement() { Remove(); }

void MatchAnnouncement::Remove() noexcept {
	if (removed_) return;
	removed_ = true;
	::unlink(path_.c_str());
}

}  // namespace kse::sim
