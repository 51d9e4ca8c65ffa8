#include <kse/sim/RobotReports.h>

#include <cstdio>
#include <iostream>
#include <map>
#include <mutex>
#include <utility>

namespace kse::sim {

struct RobotReports::Shared {
	struct Repeats {
		std::size_t seen = 0;
		std::size_t pending = 0;  // not printed since the last line about this message
		std::chrono::steady_clock::time_point last_line{};
	};

	explicit Shared(Limits l) : limits(l) {}

	void Print(const std::string& line) {  // under mutex
		++printed;
		if (printer) {
			printer(line);
		} else {
			std::cerr << line + "\n" << std::flush;
		}
	}

	static std::string Repeated(const std::string& line, std::size_t times) {
		return line + " (" + std::to_string(times) + " more time" + (times == 1 ? "" : "s") + ")";
	}

	void Take(const std::string& robot, const std::string& behaviour, const statechart_engine::EngineReport& report) {
		Listener listen;
		{
			std::lock_guard<std::mutex> lock(mutex);
			listen = listener;
		}
		if (listen) listen({robot, behaviour, report});

		const std::string line = "[" + robot + " " + behaviour + "] statechart '" + report.chart + "': " + report.text;
		const auto now = std::chrono::steady_clock::now();
		std::lock_guard<std::mutex> lock(mutex);
		Repeats& repeats = messages[line];
		if (++repeats.seen <= limits.first) {
			Print(line);
			repeats.last_line = now;
			return;
		}
		++repeats.pending;
		++suppressed;
		if (now - repeats.last_line >= limits.period) {
			Print(Repeated(line, repeats.pending));
			repeats.pending = 0;
			repeats.last_line = now;
		}
	}

	Limits limits;
	mutable std::mutex mutex;
	Printer printer;
	Listener listener;
	std::map<std::string, Repeats> messages;  // by line: robot and message
	std::size_t printed = 0;
	std::size_t suppressed = 0;
};

RobotReports::RobotReports() : RobotReports(Limits{}) {}

RobotReports::RobotReports(Limits limits) : shared_(std::make_shared<Shared>(limits)) {}

void RobotReports::SetPrinter(Printer printer) {
	std::lock_guard<std::mutex> lock(shared_->mutex);
	shared_->printer = std::move(printer);
}

void RobotReports::SetListener(Listener listener) {
	std::lock_guard<std::mutex> lock(shared_->mutex);
	shared_->listener = std::move(listener);
}

statechart_engine::Reporter RobotReports::For(const std::string& robot, const std::string& behaviour) {
	return [shared = shared_, robot, behaviour](const statechart_engine::EngineReport& report) { shared->Take(robot, behaviour, report); };
}

void RobotReports::Flush() {
	std::lock_guard<std::mutex> lock(shared_->mutex);
	for (auto& [line, repeats] : shared_->messages) {
		if (repeats.pending == 0) continue;
		shared_->Print(Shared::Repeated(line, repeats.pending));
		repeats.pending = 0;
	}
}

std::size_t RobotReports::Printed() const {
	std::lock_guard<std::mutex> lock(shared_->mutex);
	return shared_->printed;
}

std::size_t RobotReports::Suppressed() const {
	std::lock_guard<std::mutex> lock(shared_->mutex);
	return shared_->suppressed;
}

}  // namespace kse::sim
