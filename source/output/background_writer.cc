#include <deal.II/base/exceptions.h>

#include <hemicontact/output/background_writer.h>

#include <exception>

namespace hemicontact
{
  BackgroundWriter::~BackgroundWriter()
  {
    if (job_result.valid())
      job_result.wait();
    if (retirement.valid())
      retirement.wait();
  }

  void
  BackgroundWriter::start(std::function<std::string()> job,
                          const std::launch            policy)
  {
    Assert(!pending(), dealii::ExcMessage("wait() for the previous job first"));
    if (retirement.valid())
      retirement.wait();
    job_result = std::async(policy, [job = std::move(job)]() -> std::string {
      try
        {
          return job();
        }
      catch (const std::exception &e)
        {
          return e.what();
        }
      catch (...)
        {
          return "an unknown error";
        }
    });
  }

  void
  BackgroundWriter::retire(std::vector<std::shared_ptr<void>> buffers)
  {
    if (retirement.valid())
      retirement.wait();
    retirement =
      std::async(std::launch::async,
                 [buffers = std::move(buffers)]() mutable { buffers.clear(); });
  }

  std::string
  BackgroundWriter::wait()
  {
    return job_result.valid() ? job_result.get() : std::string();
  }
} // namespace hemicontact
