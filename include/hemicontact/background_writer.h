#pragma once

#include <functional>
#include <future>
#include <string>

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
    /** Waits for the job in progress. */
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

  private:
    std::future<std::string> job_result;
  };
} // namespace hemicontact
