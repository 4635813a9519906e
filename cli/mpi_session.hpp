// One rank of an MPI job, for `zdg transform dt|voronoi --mpi` (issue #15): the collective
// operations of the distributed transform (kernel/transforms/distributed_transform.hpp) over
// MPI_COMM_WORLD, and the MPI-IO reads and writes of the .npy slabs and column blocks; for
// `zdg converge|paper --mpi` (issue #40, cli/mpi_sweep.hpp): tagged messages between ranks. The
// session asks for MPI_THREAD_SERIALIZED (one thread at a time may call MPI). mpi.h is
// included by cli/mpi_session.cpp only; a zdg built without MPI (no
// libopenmpi-dev at configure time) compiles the same class with every call refused.
#pragma once

#include <zdg/kernel/transforms/distributed_transform.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace zdg::cli {

class MpiSession final : public RankExchange {
public:
  /// Whether this zdg was built with MPI.
  static bool built();
  /// Whether the process was started by an MPI launcher (mpirun, mpiexec, srun: their
  /// environment variables), not as a singleton.
  static bool launched();

  /// MPI_Init (InvalidArgument when not built() or not launched(), with the command to use).
  MpiSession();
  /// MPI_Finalize.
  ~MpiSession() override;
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  int rank() const override { return rank_; }
  int size() const override { return size_; }
  /// The ranks running on this machine (MPI_COMM_TYPE_SHARED).
  int local_size() const { return local_size_; }
  void sendrecv(int to, const void* send, std::uint64_t send_bytes, int from, void* recv,
                std::uint64_t recv_bytes) override;
  std::uint64_t max_over_ranks(std::uint64_t value) override;
  std::uint64_t min_over_ranks(std::uint64_t value);
  /// Rank root's text on every rank.
  std::string broadcast(const std::string& text, int root);
  /// Ends the whole job with this exit status (MPI_Abort): for a failure on some ranks only,
  /// which the others, waiting in a collective step, could not see.
  [[noreturn]] void abort(int status);

  /// Whether threads may call the session one at a time (MPI_THREAD_SERIALIZED granted).
  bool serialized() const { return serialized_; }

  /// A message between two ranks: its sender, its tag and its bytes.
  struct Message {
    int source = 0, tag = 0;
    std::string bytes;
  };
  /// Sends `bytes` (at most 2^31 - 1) to rank `to` with tag `tag` (0..32767) (MPI_Send).
  void send(int to, int tag, const std::string& bytes);
  /// The next message from rank `from` (-1: any rank) with tag `tag` (-1: any tag) when one
  /// has arrived (MPI_Iprobe, then MPI_Recv of its size), none otherwise; messages of one
  /// sender arrive in the order sent.
  std::optional<Message> try_receive(int from, int tag);
  /// Waits for such a message, polling with sleeps of 0.1 to 2 ms: a rank that waits leaves
  /// its core to the ranks that compute (MPI's blocking receive spins on it, which an
  /// oversubscribed machine pays for).
  Message receive(int from, int tag);

  /// Reads `bytes` bytes of the file from byte `offset` (independent MPI-IO reads, in pieces
  /// of at most 1 GiB); IoError on failure.
  void read(const std::string& path, std::uint64_t offset, void* data, std::uint64_t bytes);
  /// Collective write of `rows` rows of row_bytes bytes (contiguous in data) to the file, row i
  /// at byte offset + i * stride: a column block of an array in C order (MPI-IO file view of an
  /// hvector type, MPI_File_write_all). Every rank calls it, possibly with 0 rows or bytes.
  void write_rows(const std::string& path, std::uint64_t offset, std::uint64_t row_bytes,
                  std::uint64_t stride, std::int64_t rows, const void* data);

private:
  int rank_ = 0, size_ = 1, local_size_ = 1;
  bool serialized_ = false;
};

} // namespace zdg::cli
