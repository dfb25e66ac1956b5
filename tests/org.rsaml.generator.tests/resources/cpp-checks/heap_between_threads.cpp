/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// A check of the C++ runtime's send path (CppRuntimeTest): a sender thread sends numbers and text to a module whose
// worker serves its data at the default priority, as a real-time release sends to a module with aperiodic reactions.
// Every block operator new hands out carries the number of the thread that allocated it; in the steady state (after
// each mailbox slot has held a message once), the check counts the blocks the sender allocates and the blocks any
// thread frees that another thread allocated. It prints
//   sender-allocations N crossed-frees M handled H dropped D
// and the test asserts: no block crosses between threads, and, without the trace, the sender allocates nothing.
// Arguments: "quiet" or "traced".
#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <string>
#include <thread>

#include "rsaml/runtime.hpp"

namespace {

std::atomic<int> next_thread{1};
thread_local int thread_number = 0;

int this_thread_number() {
  if (thread_number == 0) {
    thread_number = next_thread.fetch_add(1);
  }
  return thread_number;
}

// The header before each block: the allocating thread's number (a full alignment unit, so the block stays aligned).
constexpr std::size_t HEADER = alignof(std::max_align_t);

std::atomic<bool> counting{false};
std::atomic<int> sender{0};
std::atomic<long> sender_allocations{0};
std::atomic<long> crossed_frees{0};

void* allocate(std::size_t size) {
  char* block = static_cast<char*>(std::malloc(size + HEADER));
  if (block == nullptr) {
    return nullptr;
  }
  const int me = this_thread_number();
  std::memcpy(block, &me, sizeof me);
  if (counting.load() && me == sender.load()) {
    sender_allocations.fetch_add(1);
  }
  return block + HEADER;
}

void release(void* p) {
  if (p == nullptr) {
    return;
  }
  char* block = static_cast<char*>(p) - HEADER;
  int owner;
  std::memcpy(&owner, block, sizeof owner);
  if (counting.load() && owner != this_thread_number()) {
    crossed_frees.fetch_add(1);
  }
  std::free(block);
}

}  // namespace

void* operator new(std::size_t size) {
  if (void* p = allocate(size)) {
    return p;
  }
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) { return operator new(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept { return allocate(size); }
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept { return allocate(size); }
void operator delete(void* p) noexcept { release(p); }
void operator delete[](void* p) noexcept { release(p); }
void operator delete(void* p, std::size_t) noexcept { release(p); }
void operator delete[](void* p, std::size_t) noexcept { release(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { release(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { release(p); }

namespace {

class Source : public rsaml::Module {
 public:
  explicit Source(rsaml::System& system) : Module(system, "check/source"), number(*this, "number"), text(*this, "text") {}
  rsaml::Output<double> number;
  rsaml::Output<std::string> text;
};

class Sink : public rsaml::Module {
 public:
  explicit Sink(rsaml::System& system)
      : Module(system, "check/sink"),
        number(*this, "number", [this](const double& v) { sum += v; handled.fetch_add(1); }),
        text(*this, "text", [this](const std::string& v) { chars += v.size(); handled.fetch_add(1); }) {
    serve_data_unbounded();  // its worker at the default priority, as for aperiodic reactions
  }
  rsaml::Input<double> number;
  rsaml::Input<std::string> text;
  std::atomic<long> handled{0};
  double sum = 0;
  std::size_t chars = 0;
};

}  // namespace

int main(int argc, char** argv) {
  const bool traced = argc > 1 && std::strcmp(argv[1], "traced") == 0;
  rsaml::Trace::configure(traced, rsaml::Clock::now());
  rsaml::System system("check");
  Source source(system);
  Sink sink(system);
  source.number.connect(sink.number);
  source.text.connect(sink.text);
  sink.start_worker();
  // longer than any small-string buffer: a slot's copy allocates until the slot has held such a text once
  const std::string text = "a message of some sixty characters, past the small-string buffer";
  long sent = 0;
  const auto settle = [&] {  // until the worker has handled, or the mailbox dropped, every message sent
    while (sink.handled.load() + static_cast<long>(sink.mail_dropped()) < sent) {
      std::this_thread::sleep_for(std::chrono::microseconds(50));
    }
  };
  const auto paced = [&](int messages) {  // the worker keeps up: every slot in turn
    for (int i = 0; i < messages; ++i) {
      source.number.send(i);
      source.text.send(text);
      sent += 2;
      settle();
    }
  };
  const auto flood = [&](int messages) {  // faster than the worker: the mailbox fills and drops
    for (int i = 0; i < messages; ++i) {
      source.number.send(i);
      source.text.send(text);
      sent += 2;
    }
    settle();
  };
  // each slot of the mailbox (and so each slot of the text port) holds a text once, texts alone, one at a time
  for (std::size_t i = 0; i < 2 * rsaml::MAILBOX_SLOTS; ++i) {
    source.text.send(text);
    sent += 1;
    settle();
  }
  paced(static_cast<int>(rsaml::MAILBOX_SLOTS));
  flood(1000);

  sender.store(this_thread_number());
  counting.store(true);
  paced(2000);
  flood(2000);
  paced(200);
  counting.store(false);

  std::printf("sender-allocations %ld crossed-frees %ld handled %ld dropped %llu\n", sender_allocations.load(), crossed_frees.load(),
              sink.handled.load(), static_cast<unsigned long long>(sink.mail_dropped()));
  std::fflush(stdout);
  sink.stop_worker();
  rsaml::Trace::flush();
  return 0;
}
