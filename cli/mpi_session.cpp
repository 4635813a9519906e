// See cli/mpi_session.hpp. Compiled with ZDG_HAVE_MPI=1 when CMake found MPI
// (CMakeLists.txt, option ZDG_MPI); otherwise every call is refused with a clear error.
#include <zdg/arith/error.hpp>
#include <zdg/cli/mpi_session.hpp>

#include <algorithm>
#include <chrono>
#include <climits>
#include <cstdlib>
#include <thread>
#include <vector>

#ifdef ZDG_HAVE_MPI
#include <mpi.h>
#endif

namespace zdg::cli {

bool MpiSession::launched() {
  // OpenMPI's mpirun, PMIx launchers (OpenMPI 5, Slurm), MPICH's Hydra and Intel MPI.
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE", "PMI_RANK"}) {
    if (std::getenv(v) != nullptr) return true;
  }
  return false;
}

#ifdef ZDG_HAVE_MPI

namespace {

constexpr std::uint64_t kPiece = std::uint64_t{1} << 30; // bytes per MPI call (int counts)

std::string mpi_error(int code) {
  char text[MPI_MAX_ERROR_STRING];
  int len = 0;
  if (MPI_Error_string(code, text, &len) != MPI_SUCCESS) return "MPI error " + std::to_string(code);
  return std::string(text, static_cast<std::size_t>(len));
}

void check_io(int code, const std::string& path, const char* what) {
  if (code != MPI_SUCCESS) throw IoError(path + ": MPI-IO " + what + " failed: " + mpi_error(code));
}

} // namespace

bool MpiSession::built() {
  return true;
}

MpiSession::MpiSession() {
  if (!launched()) {
    throw InvalidArgument("--mpi: not started by an MPI launcher (run it as mpirun -np P zdg ... "
                          "--mpi)");
  }
  int ready = 0, level = MPI_THREAD_SINGLE;
  MPI_Initialized(&ready);
  if (ready == 0 &&
      MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SERIALIZED, &level) != MPI_SUCCESS) {
    throw IoError("--mpi: MPI_Init failed");
  }
  if (ready != 0) MPI_Query_thread(&level);
  serialized_ = level >= MPI_THREAD_SERIALIZED;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  MPI_Comm local;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &local);
  MPI_Comm_size(local, &local_size_);
  MPI_Comm_free(&local);
}

MpiSession::~MpiSession() {
  int done = 0;
  MPI_Finalized(&done);
  if (done == 0) MPI_Finalize();
}

void MpiSession::sendrecv(int to, const void* send, std::uint64_t send_bytes, int from, void* recv,
                          std::uint64_t recv_bytes) {
  // Pieces of at most 1 GiB each way, all posted at once (the two directions have their own
  // number of pieces; messages between two ranks arrive in the order sent).
  std::vector<MPI_Request> requests;
  auto* in = static_cast<char*>(recv);
  const auto* out = static_cast<const char*>(send);
  for (std::uint64_t at = 0; at < recv_bytes; at += kPiece) {
    requests.emplace_back();
    MPI_Irecv(in + at, static_cast<int>(std::min(kPiece, recv_bytes - at)), MPI_BYTE, from, 15,
              MPI_COMM_WORLD, &requests.back());
  }
  for (std::uint64_t at = 0; at < send_bytes; at += kPiece) {
    requests.emplace_back();
    MPI_Isend(out + at, static_cast<int>(std::min(kPiece, send_bytes - at)), MPI_BYTE, to, 15,
              MPI_COMM_WORLD, &requests.back());
  }
  MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
}

std::uint64_t MpiSession::max_over_ranks(std::uint64_t value) {
  std::uint64_t m = 0;
  MPI_Allreduce(&value, &m, 1, MPI_UINT64_T, MPI_MAX, MPI_COMM_WORLD);
  return m;
}

std::uint64_t MpiSession::min_over_ranks(std::uint64_t value) {
  std::uint64_t m = 0;
  MPI_Allreduce(&value, &m, 1, MPI_UINT64_T, MPI_MIN, MPI_COMM_WORLD);
  return m;
}

std::string MpiSession::broadcast(const std::string& text, int root) {
  std::uint64_t n = text.size();
  MPI_Bcast(&n, 1, MPI_UINT64_T, root, MPI_COMM_WORLD);
  std::string out = rank_ == root ? text : std::string(n, '\0');
  MPI_Bcast(out.data(), static_cast<int>(n), MPI_CHAR, root, MPI_COMM_WORLD);
  return out;
}

void MpiSession::abort(int status) {
  MPI_Abort(MPI_COMM_WORLD, status);
  std::_Exit(status);
}

void MpiSession::send(int to, int tag, const std::string& bytes) {
  if (bytes.size() > static_cast<std::size_t>(INT_MAX)) {
    throw InvalidArgument("--mpi: a message of " + std::to_string(bytes.size()) +
                          " bytes exceeds MPI's int counts");
  }
  const int code =
      MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, to, tag, MPI_COMM_WORLD);
  if (code != MPI_SUCCESS) throw IoError("--mpi: MPI_Send failed: " + mpi_error(code));
}

std::optional<MpiSession::Message> MpiSession::try_receive(int from, int tag) {
  int arrived = 0;
  MPI_Status st;
  MPI_Iprobe(from < 0 ? MPI_ANY_SOURCE : from, tag < 0 ? MPI_ANY_TAG : tag, MPI_COMM_WORLD,
             &arrived, &st);
  if (arrived == 0) return std::nullopt;
  int n = 0;
  MPI_Get_count(&st, MPI_BYTE, &n);
  Message m{st.MPI_SOURCE, st.MPI_TAG, std::string(static_cast<std::size_t>(n), '\0')};
  const int code =
      MPI_Recv(m.bytes.data(), n, MPI_BYTE, m.source, m.tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  if (code != MPI_SUCCESS) throw IoError("--mpi: MPI_Recv failed: " + mpi_error(code));
  return m;
}

MpiSession::Message MpiSession::receive(int from, int tag) {
  auto pause = std::chrono::microseconds(100);
  for (;;) {
    if (auto m = try_receive(from, tag)) return std::move(*m);
    std::this_thread::sleep_for(pause);
    pause = std::min<std::chrono::microseconds>(pause * 2, std::chrono::milliseconds(2));
  }
}

void MpiSession::read(const std::string& path, std::uint64_t offset, void* data,
                      std::uint64_t bytes) {
  MPI_File fh;
  check_io(MPI_File_open(MPI_COMM_SELF, path.c_str(), MPI_MODE_RDONLY, MPI_INFO_NULL, &fh), path,
           "open");
  auto* p = static_cast<char*>(data);
  for (std::uint64_t at = 0; at < bytes; at += kPiece) {
    const int n = static_cast<int>(std::min(kPiece, bytes - at));
    MPI_Status st;
    const int code =
        MPI_File_read_at(fh, static_cast<MPI_Offset>(offset + at), p + at, n, MPI_BYTE, &st);
    int got = 0;
    MPI_Get_count(&st, MPI_BYTE, &got);
    if (code != MPI_SUCCESS || got != n) {
      MPI_File_close(&fh);
      check_io(code, path, "read");
      throw IoError(path + ": short read (" + std::to_string(got) + " of " + std::to_string(n) +
                    " bytes at " + std::to_string(offset + at) + ")");
    }
  }
  check_io(MPI_File_close(&fh), path, "close");
}

void MpiSession::write_rows(const std::string& path, std::uint64_t offset, std::uint64_t row_bytes,
                            std::uint64_t stride, std::int64_t rows, const void* data) {
  if (row_bytes > static_cast<std::uint64_t>(INT_MAX) || rows > INT_MAX) {
    throw InvalidArgument(path + ": rows of " + std::to_string(row_bytes) + " bytes (" +
                          std::to_string(rows) + " rows) exceed MPI-IO's int counts");
  }
  MPI_File fh;
  check_io(MPI_File_open(MPI_COMM_WORLD, path.c_str(), MPI_MODE_WRONLY, MPI_INFO_NULL, &fh), path,
           "open");
  const bool empty = rows == 0 || row_bytes == 0;
  MPI_Datatype row = MPI_BYTE, view = MPI_BYTE;
  if (!empty) {
    MPI_Type_contiguous(static_cast<int>(row_bytes), MPI_BYTE, &row);
    MPI_Type_commit(&row);
    MPI_Type_create_hvector(static_cast<int>(rows), 1, static_cast<MPI_Aint>(stride), row, &view);
    MPI_Type_commit(&view);
  }
  int code = MPI_File_set_view(fh, empty ? 0 : static_cast<MPI_Offset>(offset), MPI_BYTE, view,
                               "native", MPI_INFO_NULL);
  if (code == MPI_SUCCESS) {
    MPI_Status st;
    code = MPI_File_write_all(fh, data, empty ? 0 : static_cast<int>(rows), row, &st);
  }
  if (!empty) {
    MPI_Type_free(&view);
    MPI_Type_free(&row);
  }
  const int closed = MPI_File_close(&fh);
  check_io(code, path, "write");
  check_io(closed, path, "close");
}

#else // built without MPI: the same class, refused

bool MpiSession::built() {
  return false;
}

MpiSession::MpiSession() {
  throw InvalidArgument("--mpi: this zdg was built without MPI (install Debian's libopenmpi-dev, "
                        "then configure and build again)");
}
MpiSession::~MpiSession() = default;
void MpiSession::sendrecv(int, const void*, std::uint64_t, int, void*, std::uint64_t) {}
std::uint64_t MpiSession::max_over_ranks(std::uint64_t value) {
  return value;
}
std::uint64_t MpiSession::min_over_ranks(std::uint64_t value) {
  return value;
}
std::string MpiSession::broadcast(const std::string& text, int) {
  return text;
}
void MpiSession::abort(int status) {
  std::_Exit(status);
}
void MpiSession::send(int, int, const std::string&) {}
std::optional<MpiSession::Message> MpiSession::try_receive(int, int) {
  return std::nullopt;
}
MpiSession::Message MpiSession::receive(int, int) {
  return {};
}
void MpiSession::read(const std::string&, std::uint64_t, void*, std::uint64_t) {}
void MpiSession::write_rows(const std::string&, std::uint64_t, std::uint64_t, std::uint64_t,
                            std::int64_t, const void*) {}

#endif

} // namespace zdg::cli
