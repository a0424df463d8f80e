#include "root_status.h"
#include <stdexcept>

namespace damseis::geometry
{
std::string broadcast_from_root(MPI_Comm comm, std::string text, int root)
{
  int length = static_cast<int>(text.size());
  MPI_Bcast(&length, 1, MPI_INT, root, comm);
  text.resize(static_cast<std::size_t>(length));
  MPI_Bcast(text.data(), length, MPI_CHAR, root, comm);
  return text;
}

void check_root_status(MPI_Comm comm, bool ok, const std::string& message,
                       bool invalid)
{
  int flag[2] = {ok ? 1 : 0, invalid ? 1 : 0};
  MPI_Bcast(flag, 2, MPI_INT, 0, comm);
  if (flag[0])
    return;
  const std::string text = broadcast_from_root(comm, message);
  if (flag[1])
    throw std::invalid_argument(text);
  throw std::runtime_error(text);
}

void on_root(MPI_Comm comm, const std::function<void()>& work,
             const RootErrors& errors)
{
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  bool ok = true, invalid = false;
  std::string message;
  if (rank == 0)
  {
    try
    {
      work();
    }
    catch (const std::invalid_argument& e)
    {
      ok = false;
      invalid = errors.keep_invalid;
      message = invalid ? e.what() : errors.prefix + e.what();
    }
    catch (const std::exception& e)
    {
      ok = false;
      message = errors.prefix + e.what();
    }
    catch (...)
    {
      ok = false;
      message = errors.unknown;
    }
  }
  check_root_status(comm, ok, message, invalid);
}
} // namespace damseis::geometry
