#pragma once
// A machine with no CPU to spare, for the tests of what threads do under load: threads that spin,
// twice as many as the CPUs this process may run on, for as long as the object lives. Every other runnable
// thread then waits for a CPU about half of its time.
#include <sched.h>

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace roughgas {

class BusyMachine {
  public:
    BusyMachine() {
        cpu_set_t mask;
        const int cpus = sched_getaffinity(0, sizeof mask, &mask) == 0
                             ? CPU_COUNT(&mask)
                             : static_cast<int>(std::thread::hardware_concurrency());
        for (int k = 0; k < 2 * std::max(1, cpus); ++k)
            spinners_.emplace_back([this] {
                while (!stop_.load(std::memory_order_relaxed)) {
                }
            });
    }
    ~BusyMachine() {
        stop_ = true;
        for (std::thread& s : spinners_)
            s.join();
    }
    BusyMachine(const BusyMachine&) = delete;
    BusyMachine& operator=(const BusyMachine&) = delete;

  private:
    std::atomic<bool> stop_{false};
    std::vector<std::thread> spinners_;
};

} // namespace roughgas
