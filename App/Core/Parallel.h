// Running independent tasks on a few threads: the exploration's rounds (thesis 5.3.3) and the layout
// search's starts.
#pragma once

#include <algorithm>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace fabguide {

/// The threads this machine runs at once (at least 1).
inline int cores()
{
    return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

/// Runs tasks 0..count-1 on `threads` threads (or the caller's), reporting progress on the caller's thread.
template <class Task>
void runAll(int count, int threads, Task&& task, const std::function<void(int)>& finished)
{
    if (threads <= 1) {
        for (int t = 0; t < count; ++t) {
            task(t);
            finished(t);
        }
        return;
    }
    std::mutex mutex;
    std::condition_variable changed;
    std::vector<int> done;  // tasks in the order they finished
    std::exception_ptr failure;
    // Started by a fixed count: `working` is read under the lock, as a quick thread may be done before the
    // next starts.
    const int spawned = std::min(threads, count);
    int next = 0, working = spawned;
    const auto work = [&] {
        std::unique_lock<std::mutex> lock(mutex);
        while (next < count && !failure) {
            const int t = next++;
            lock.unlock();
            try {
                task(t);
            } catch (...) {
                lock.lock();
                failure = std::current_exception();
                break;
            }
            lock.lock();
            done.push_back(t);
            changed.notify_one();
        }
        --working;
        changed.notify_one();
    };
    std::vector<std::thread> pool;
    for (int k = 0; k < spawned; ++k)
        pool.emplace_back(work);
    {
        std::unique_lock<std::mutex> lock(mutex);
        for (size_t reported = 0;;) {
            changed.wait(lock, [&] { return reported < done.size() || working == 0; });
            while (reported < done.size()) {
                const int t = done[reported++];
                lock.unlock();
                finished(t);
                lock.lock();
            }
            if (working == 0)
                break;
        }
    }
    for (std::thread& thread : pool)
        thread.join();
    if (failure)
        std::rethrow_exception(failure);
}

}  // namespace fabguide
