#include "hexadapt/core/parallel.h"

#include <atomic>
#include <condition_variable>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "hexadapt/core/error.h"

namespace hexadapt {

namespace {

int hardware_threads() {
  const unsigned n = std::thread::hardware_concurrency();
  return n > 0 ? static_cast<int>(n) : 1;
}

int default_threads() {
  if (const char* env = std::getenv("OMP_NUM_THREADS")) {
    char* end = nullptr;
    const long n = std::strtol(env, &end, 10);
    if (end != env && n > 0 && n <= 4096) return static_cast<int>(n);
  }
  return hardware_threads();
}

std::atomic<int>& thread_count() {
  static std::atomic<int> count{default_threads()};
  return count;
}

// Set on a thread while it runs its share of a loop: a loop inside runs on that thread alone.
thread_local bool in_loop = false;

// Worker threads, started on first use and kept. Each waits on `wake` for a new job (a higher
// `generation`); the caller runs its own share, then waits on `done` until every worker of the
// job has run its share. Waiting threads sleep.
class Pool {
 public:
  ~Pool() {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    wake_.notify_all();
    for (std::thread& t : workers_) t.join();
  }

  void run(int threads, const std::function<void(int)>& body) {
    if (in_loop) return serial(threads, body);
    const std::unique_lock<std::mutex> busy(busy_, std::try_to_lock);
    if (!busy.owns_lock()) return serial(threads, body);
    std::vector<std::exception_ptr> errors(static_cast<std::size_t>(threads));
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      while (static_cast<int>(workers_.size()) < threads - 1) {
        const int index = static_cast<int>(workers_.size()) + 1;
        workers_.emplace_back([this, index] { work(index); });
      }
      body_ = &body;
      errors_ = &errors;
      threads_ = threads;
      pending_ = threads - 1;
      ++generation_;
    }
    wake_.notify_all();
    share(0, body, errors);
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [this] { return pending_ == 0; });
    body_ = nullptr;
    lock.unlock();
    for (const std::exception_ptr& e : errors)
      if (e) std::rethrow_exception(e);
  }

 private:
  static void serial(int threads, const std::function<void(int)>& body) {
    for (int k = 0; k < threads; ++k) body(k);
  }

  static void share(int k, const std::function<void(int)>& body,
                    std::vector<std::exception_ptr>& errors) {
    in_loop = true;
    try {
      body(k);
    } catch (...) {
      errors[static_cast<std::size_t>(k)] = std::current_exception();
    }
    in_loop = false;
  }

  void work(int index) {
    std::uint64_t seen = 0;
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
      if (stop_) return;
      seen = generation_;
      if (index >= threads_) continue;
      const std::function<void(int)>& body = *body_;
      std::vector<std::exception_ptr>& errors = *errors_;
      lock.unlock();
      share(index, body, errors);
      lock.lock();
      if (--pending_ == 0) done_.notify_one();
    }
  }

  std::mutex busy_;   // held by the thread running a job
  std::mutex mutex_;  // guards what follows
  std::condition_variable wake_, done_;
  std::vector<std::thread> workers_;
  const std::function<void(int)>* body_ = nullptr;
  std::vector<std::exception_ptr>* errors_ = nullptr;
  int threads_ = 0, pending_ = 0;
  std::uint64_t generation_ = 0;
  bool stop_ = false;
};

Pool& pool() {
  static Pool p;
  return p;
}

}  // namespace

void set_threads(int n) {
  if (n < 0) throw OptionError("thread count must be >= 0");
  thread_count() = n == 0 ? hardware_threads() : n;
}

int n_threads() { return thread_count(); }

namespace detail {

void run_on_threads(int threads, const std::function<void(int)>& body) {
  pool().run(threads, body);
}

}  // namespace detail

}  // namespace hexadapt
