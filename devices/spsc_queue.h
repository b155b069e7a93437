#pragma once
// Bounded single-producer/single-consumer ring (docs/architecture.md): the producer never waits on the
// consumer. try_push fails when full (the caller counts a drop); try_pop fails when empty. Several
// producer threads may share one only by taking turns under a mutex of their own (as the recorder's
// device threads do); the consumer never takes it.
// Capacity is fixed at construction, storage allocated once.
#include <atomic>
#include <cstddef>
#include <memory>
#include <utility>

namespace lmc::devices {

template <class T>
class SpscQueue {
 public:
  explicit SpscQueue(size_t capacity) : capacity_(capacity + 1), slots_(std::make_unique<T[]>(capacity + 1)) {}

  size_t capacity() const { return capacity_ - 1; }

  bool try_push(const T& value) {
    const size_t head = head_.load(std::memory_order_relaxed);
    const size_t next = head + 1 == capacity_ ? 0 : head + 1;
    if (next == tail_.load(std::memory_order_acquire)) return false;
    slots_[head] = value;
    head_.store(next, std::memory_order_release);
    return true;
  }

  bool try_pop(T& out) {
    const size_t tail = tail_.load(std::memory_order_relaxed);
    if (tail == head_.load(std::memory_order_acquire)) return false;
    out = std::move(slots_[tail]);
    tail_.store(tail + 1 == capacity_ ? 0 : tail + 1, std::memory_order_release);
    return true;
  }

  size_t size_approx() const {
    const size_t h = head_.load(std::memory_order_acquire);
    const size_t t = tail_.load(std::memory_order_acquire);
    return h >= t ? h - t : h + capacity_ - t;
  }

 private:
  size_t capacity_;
  std::unique_ptr<T[]> slots_;
  alignas(64) std::atomic<size_t> head_{0};
  alignas(64) std::atomic<size_t> tail_{0};
};

}  // namespace lmc::devices
