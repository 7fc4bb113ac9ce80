#pragma once

#include <functional>
#include <future>
#include <memory>
#include <string>
#include <vector>

namespace hemicontact
{
  /**
   * Runs one output job at a time, so that writing the solution of a step
   * overlaps the next step (doc/outputs.md, "Writing while computing"). A
   * job returns an error message (empty: success) and must not call MPI:
   * the caller checks the result collectively after wait(). The job reads
   * data the caller keeps unchanged until wait() has returned.
   */
  class BackgroundWriter
  {
  public:
    /** Waits for the job in progress and for the buffers being freed. */
    ~BackgroundWriter();

    /**
     * Start @p job after the previous one was waited for: on its own thread
     * with std::launch::async, or on the calling thread within wait() with
     * std::launch::deferred (for jobs that need MPI).
     */
    void
    start(std::function<std::string()> job, std::launch policy);

    /** Whether a job was started and not waited for yet. */
    bool
    pending() const
    {
      return job_result.valid();
    }

    /**
     * Wait for the job started last and return its error message (empty
     * when it succeeded or when none is pending); an exception the job
     * threw becomes its message.
     */
    std::string
    wait();

    /**
     * Free @p buffers (what a finished job read: its patches, its file
     * layout) on a thread of their own, so that the caller does not spend
     * the time. Their destructors must not call MPI. The next start(),
     * retire() and the destructor wait until they are freed.
     */
    void
    retire(std::vector<std::shared_ptr<void>> buffers);

  private:
    std::future<std::string> job_result;
    std::future<void>        retirement;
  };
} // namespace hemicontact
