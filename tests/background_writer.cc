// BackgroundWriter, the thread that writes the solution while the run goes
// on: an asynchronous job runs on another thread and is pending until
// waited for; the run can change its own data meanwhile; a deferred job runs
// on the calling thread within wait(); a job's error message and an
// exception it throws both come back from wait(); the next job starts only
// after wait(); retired buffers are freed on another thread, and the next job
// starts only after they are.
#include <hemicontact/output/background_writer.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

#include "tests.h"

using namespace hemicontact;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::thread::id                    caller = std::this_thread::get_id();

  BackgroundWriter writer;
  out() << "pending before any job: " << writer.pending() << "\n";
  out() << "wait without a job: '" << writer.wait() << "'\n";

  // the job copies nothing: it reads 'snapshot', kept until wait()
  const std::vector<double> snapshot = {1, 2, 3};
  std::atomic<bool>         release{false};
  std::thread::id           job_thread;
  double                    written = 0;
  writer.start(
    [&]() -> std::string {
      job_thread = std::this_thread::get_id();
      while (!release)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      for (const double v : snapshot)
        written += v;
      return "";
    },
    std::launch::async);
  // the caller goes on while the job waits for it
  double computed = 0;
  for (unsigned int i = 1; i <= 1000; ++i)
    computed += i;
  out() << "pending while the job runs: " << writer.pending()
        << ", computed meanwhile: " << computed << "\n";
  release = true;
  out() << "async job: error '" << writer.wait() << "', wrote " << written
        << ", on another thread: " << (job_thread != caller)
        << ", pending after wait: " << writer.pending() << "\n";

  writer.start([]() -> std::string { return "No space left on device"; },
               std::launch::async);
  out() << "failing job: '" << writer.wait() << "'\n";

  writer.start([]() -> std::string { throw std::runtime_error("bad file"); },
               std::launch::async);
  out() << "throwing job: '" << writer.wait() << "'\n";

  bool ran = false;
  writer.start(
    [&]() -> std::string {
      ran        = true;
      job_thread = std::this_thread::get_id();
      return "";
    },
    std::launch::deferred);
  out() << "deferred job ran before wait: " << ran;
  writer.wait();
  out() << ", after wait: " << ran
        << ", on the calling thread: " << (job_thread == caller) << "\n";

  // a buffer that is freed only once released, and records where
  struct Buffer
  {
    Buffer(const std::atomic<bool> &release,
           std::thread::id         &freed_on,
           std::atomic<int>        &freed)
      : release(release)
      , freed_on(freed_on)
      , freed(freed)
    {}
    ~Buffer()
    {
      while (!release)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      freed_on = std::this_thread::get_id();
      ++freed;
    }
    const std::atomic<bool> &release;
    std::thread::id         &freed_on;
    std::atomic<int>        &freed;
  };
  std::atomic<bool> release_buffers{false};
  std::thread::id   freed_on = caller;
  std::atomic<int>  freed{0};
  writer.retire({std::make_shared<Buffer>(release_buffers, freed_on, freed),
                 std::make_shared<Buffer>(release_buffers, freed_on, freed),
                 nullptr});
  // the caller goes on while the buffers wait to be freed
  out() << "retired buffers freed when retire returns: " << freed;
  release_buffers      = true;
  int freed_before_job = -1;
  writer.start(
    [&]() -> std::string {
      freed_before_job = freed;
      return "";
    },
    std::launch::async);
  writer.wait();
  out() << ", before the next job: " << freed_before_job
        << ", on another thread: " << (freed_on != caller) << "\n";
}
