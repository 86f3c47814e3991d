// The H5Part writer of --format hdf5 (wash/detail/hdf5_series.hpp), built
// twice: against the serial HDF5 library, and with WASH_HDF5_PARALLEL against
// parallel HDF5 (MPI-IO), where every rank writes a block of rows itself.
//
// Rows are in ascending id order in the file. Under MPI, ids are the creation
// indices 0..N-1 (docs/semantics.md), so a row's place is its id: each rank
// sends its rows to the rank whose block of ids holds them (one all-to-all of
// about its share) and writes that block as one hyperslab. No rank ever holds
// more than about its share, and no frame is gathered anywhere.
#include <wash/detail/hdf5_series.hpp>
#include <wash/detail/run_output.hpp>

#include <hdf5.h>
#ifdef WASH_HDF5_PARALLEL
#include <mpi.h>
#endif

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <numeric>
#include <utility>

namespace wash::detail {
namespace {

/// An HDF5 identifier closed by its own close function at scope exit.
class Handle {
public:
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  Handle(const Handle &) = delete;
  Handle &operator=(const Handle &) = delete;
  ~Handle() {
    if (id_ >= 0 && H5Iis_valid(id_) > 0) // fail() may have closed it
      close_(id_);
  }
  operator hid_t() const { return id_; }
  bool valid() const { return id_ >= 0; }

private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

int rankOf() {
#ifdef WASH_HDF5_PARALLEL
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
#else
  return 0;
#endif
}

class H5PartSeries final : public Hdf5Series {
public:
  H5PartSeries(std::string path, std::string partial, const std::vector<Hdf5Step> &keep)
      : path_(std::move(path)), partial_(std::move(partial)) {
    // No library shutdown at exit: after a failed write (a full disk) it
    // crashes on what the failure left; close() closes the file of a run
    // that succeeded. Before any other call, which would start the library.
    H5dont_atexit();
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); // errors become RunErrors, not stack dumps
    Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
#ifdef WASH_HDF5_PARALLEL
    H5Pset_fapl_mpio(access, MPI_COMM_WORLD, MPI_INFO_NULL);
    H5Pset_all_coll_metadata_ops(access, true);
    H5Pset_coll_metadata_write(access, true);
#endif
    if (!keep.empty() && continueFrom(keep, access))
      return;
    errno = 0;
    file_ = H5Fcreate(partial_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access);
    if (file_ < 0)
      fail("create the file");
  }
  ~H5PartSeries() override {
    if (file_ >= 0 && !parallel) // parallel: see fail()
      H5Fclose(file_);
  }

  void write(std::uint64_t step, double time, const Frame &rows,
             const std::vector<Hdf5Dataset> &datasets) override {
    const Block block = place(rows, datasets);
    const std::string name = "Step#" + std::to_string(frames_++);
    Handle group(H5Gcreate2(file_, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
    if (!group.valid())
      fail("create the group " + name);
    attribute(group, "time", H5T_NATIVE_DOUBLE, &time);
    attribute(group, "step", H5T_NATIVE_UINT64, &step);
    attribute(group, "particle_count", H5T_NATIVE_UINT64, &block.total);
    std::vector<std::uint64_t> ids(block.count);
    std::iota(ids.begin(), ids.end(), block.start);
    if (!parallel)
      for (std::size_t k = 0; k < block.count; ++k)
        ids[k] = rows.ids[block.order[k]];
    dataset(group, "id", H5T_NATIVE_UINT64, block, ids.data());
    ids = {};
    std::vector<double> values(block.count);
    for (std::size_t d = 0; d < datasets.size(); ++d) {
      block.fill(d, datasets[d], rows, values);
      dataset(group, datasets[d].name, H5T_NATIVE_DOUBLE, block, values.data());
    }
    if (H5Fflush(file_, H5F_SCOPE_GLOBAL) < 0)
      fail("flush the step " + name);
  }

  void close() override {
    const hid_t file = std::exchange(file_, -1);
    errno = 0;
    if (H5Fclose(file) < 0)
      fail("close the file");
    if (rankOf() != 0)
      return;
    std::error_code ec;
    std::filesystem::rename(partial_, path_, ec);
    if (ec)
      throw RunError("cannot write '" + path_ + "': " + ec.message());
  }

private:
#ifdef WASH_HDF5_PARALLEL
  static constexpr bool parallel = true;
#else
  static constexpr bool parallel = false;
#endif

  /// The rows of the file this process writes: [start, start + count) of
  /// `total`. Serial: every row, `order` giving the frame rows by id.
  /// Parallel: the rows received, packed id-first as `width` words each.
  struct Block {
    std::uint64_t total = 0, start = 0, count = 0;
    std::vector<std::size_t> order;
    std::vector<std::uint64_t> received;
    std::size_t width = 0;

    void fill(std::size_t d, const Hdf5Dataset &set, const Frame &rows,
              std::vector<double> &values) const {
      if (!set.column) {
        std::fill(values.begin(), values.end(), 0.0);
        return;
      }
      if (!parallel) {
        const Column &c = *set.column;
        for (std::size_t k = 0; k < count; ++k)
          values[k] = c.values[order[k] * c.components + set.component];
        return;
      }
      for (std::size_t r = 0; r < count; ++r) {
        const std::uint64_t *row = &received[r * width];
        std::memcpy(&values[row[0] - start], &row[1 + d], sizeof(double));
      }
    }
  };

  Block place(const Frame &rows, const std::vector<Hdf5Dataset> &datasets) const {
    Block b;
    if constexpr (!parallel) {
      b.total = b.count = rows.size();
      b.order.resize(rows.size());
      std::iota(b.order.begin(), b.order.end(), std::size_t(0));
      std::sort(b.order.begin(), b.order.end(),
                [&](std::size_t x, std::size_t y) { return rows.ids[x] < rows.ids[y]; });
      return b;
    }
#ifdef WASH_HDF5_PARALLEL
    int ranks = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &ranks);
    std::uint64_t local[2] = {rows.size(), 0}, global[2] = {0, 0};
    for (std::uint64_t id : rows.ids)
      local[1] = std::max(local[1], id + 1);
    MPI_Allreduce(&local[0], &global[0], 1, MPI_UINT64_T, MPI_SUM, MPI_COMM_WORLD);
    MPI_Allreduce(&local[1], &global[1], 1, MPI_UINT64_T, MPI_MAX, MPI_COMM_WORLD);
    b.total = global[0];
    if (global[1] != b.total)
      throw RunError("cannot write '" + path_ + "': the particle ids are not 0.." +
                     std::to_string(b.total) + "-1 (the largest is " + std::to_string(global[1]) +
                     "-1), which parallel HDF5 output relies on");
    const std::uint64_t per = (b.total + ranks - 1) / std::uint64_t(ranks);
    auto blockStart = [&](int r) { return std::min(b.total, per * std::uint64_t(r)); };
    int me = rankOf();
    b.start = blockStart(me);
    b.count = blockStart(me + 1) - b.start;
    b.width = 1 + datasets.size();
    // Pack every row for the rank owning its id, id first, then the values.
    std::vector<int> sendCounts(ranks, 0), sendAt(ranks, 0), recvCounts(ranks), recvAt(ranks);
    auto owner = [&](std::uint64_t id) { return int(per ? id / per : 0); };
    for (std::uint64_t id : rows.ids)
      sendCounts[owner(id)] += int(b.width);
    for (int r = 1; r < ranks; ++r)
      sendAt[r] = sendAt[r - 1] + sendCounts[r - 1];
    std::vector<std::uint64_t> send(rows.size() * b.width);
    std::vector<int> next = sendAt;
    for (std::size_t p = 0; p < rows.size(); ++p) {
      std::uint64_t *row = &send[std::size_t(next[owner(rows.ids[p])])];
      next[owner(rows.ids[p])] += int(b.width);
      row[0] = rows.ids[p];
      for (std::size_t d = 0; d < datasets.size(); ++d) {
        const Column *c = datasets[d].column;
        const double v = c ? c->values[p * c->components + datasets[d].component] : 0.0;
        std::memcpy(&row[1 + d], &v, sizeof v);
      }
    }
    MPI_Alltoall(sendCounts.data(), 1, MPI_INT, recvCounts.data(), 1, MPI_INT, MPI_COMM_WORLD);
    std::size_t received = 0;
    for (int r = 0; r < ranks; ++r) {
      recvAt[r] = int(received);
      received += std::size_t(recvCounts[r]);
    }
    if (received != b.count * b.width)
      throw RunError("cannot write '" + path_ + "': the particle ids are not distinct");
    b.received.resize(received);
    MPI_Alltoallv(send.data(), sendCounts.data(), sendAt.data(), MPI_UINT64_T, b.received.data(),
                  recvCounts.data(), recvAt.data(), MPI_UINT64_T, MPI_COMM_WORLD);
#endif
    return b;
  }

  void attribute(hid_t group, const char *name, hid_t type, const void *value) {
    Handle space(H5Screate(H5S_SCALAR), H5Sclose);
    Handle attr(H5Acreate2(group, name, type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    if (!attr.valid() || H5Awrite(attr, type, value) < 0)
      fail(std::string("write the attribute ") + name);
  }

  void dataset(hid_t group, const std::string &name, hid_t type, const Block &b,
               const void *values) {
    const hsize_t total = b.total, start = b.start, count = b.count, one = 1;
    Handle file(H5Screate_simple(1, &total, nullptr), H5Sclose);
    Handle set(H5Dcreate2(group, name.c_str(), type, file, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
               H5Dclose);
    if (!set.valid())
      fail("create the dataset " + name);
    Handle memory(H5Screate_simple(1, count ? &count : &one, nullptr), H5Sclose);
    if (count)
      H5Sselect_hyperslab(file, H5S_SELECT_SET, &start, nullptr, &count, nullptr);
    else {
      H5Sselect_none(file);
      H5Sselect_none(memory);
    }
    Handle transfer(H5Pcreate(H5P_DATASET_XFER), H5Pclose);
#ifdef WASH_HDF5_PARALLEL
    H5Pset_dxpl_mpio(transfer, H5FD_MPIO_COLLECTIVE);
#endif
    errno = 0;
    if (H5Dwrite(set, type, memory, file, transfer, values) < 0)
      fail("write the dataset " + name);
  }

  /// A restart into the folder of the run it continues: `partial` a copy of
  /// `path` whose groups are `keep` (those after them dropped), the next
  /// group after them. Without `path`, the `partial` a killed run left is
  /// continued in place (never truncated). False where there is neither.
  bool continueFrom(const std::vector<Hdf5Step> &keep, hid_t access) {
    // One answer for every rank: rank 0's (it copies the file).
    int how = 0; // 1: copied; 2: the partial file continued; -1: copying failed
    int error = 0;
    if (rankOf() == 0 && std::filesystem::exists(path_)) {
      std::error_code ec;
      std::filesystem::copy_file(path_, partial_, std::filesystem::copy_options::overwrite_existing,
                                 ec);
      how = ec ? -1 : 1;
      error = ec.value();
    } else if (rankOf() == 0 && std::filesystem::exists(partial_))
      how = 2;
#ifdef WASH_HDF5_PARALLEL
    int answer[2] = {how, error};
    MPI_Bcast(answer, 2, MPI_INT, 0, MPI_COMM_WORLD);
    how = answer[0];
    error = answer[1];
#endif
    if (how == 0)
      return false;
    if (how < 0) {
      removePartial();
      throw RunError("cannot continue '" + path_ + "' after the checkpoint: copying it to '" +
                     partial_ + "' failed: " + std::strerror(error));
    }
    if (how == 2)
      continued_ = partial_;
    file_ = H5Fopen(partial_.c_str(), H5F_ACC_RDWR, access);
    if (file_ < 0)
      refuse("HDF5 cannot open it");
    for (std::size_t k = 0; k < keep.size(); ++k) {
      const std::string name = "Step#" + std::to_string(k);
      std::uint64_t step = 0;
      double time = 0.0;
      if (H5Lexists(file_, name.c_str(), H5P_DEFAULT) <= 0 ||
          !readAttribute(name, "step", H5T_NATIVE_UINT64, &step) ||
          !readAttribute(name, "time", H5T_NATIVE_DOUBLE, &time))
        refuse("it has no group " + name + " with a step and a time, the checkpoint's frame " +
               std::to_string(k) + " (iteration " + std::to_string(keep[k].step) + ")");
      if (step != keep[k].step || time != keep[k].time) {
        char text[320];
        std::snprintf(text, sizeof text,
                      "its %s is iteration %llu at t = %.17g, the checkpoint's frame %zu "
                      "iteration %llu at t = %.17g",
                      name.c_str(), (unsigned long long)step, time, k,
                      (unsigned long long)keep[k].step, keep[k].time);
        refuse(text);
      }
    }
    // The groups after them: frames past the checkpoint, recomputed now.
    H5G_info_t info;
    if (H5Gget_info(file_, &info) < 0)
      refuse("HDF5 cannot list its groups");
    std::vector<std::string> past;
    for (hsize_t i = 0; i < info.nlinks; ++i) {
      char name[64] = "";
      if (H5Lget_name_by_idx(file_, ".", H5_INDEX_NAME, H5_ITER_INC, i, name, sizeof name,
                             H5P_DEFAULT) < 0)
        continue; // a longer name: no Step#k
      unsigned long long k = 0;
      int end = 0;
      if (std::sscanf(name, "Step#%llu%n", &k, &end) == 1 && name[end] == '\0' && k >= keep.size())
        past.push_back(name);
    }
    for (const std::string &name : past)
      if (H5Ldelete(file_, name.c_str(), H5P_DEFAULT) < 0)
        fail("remove the group " + name + " (past the checkpoint)");
    frames_ = keep.size();
    return true;
  }

  bool readAttribute(const std::string &group, const char *name, hid_t type, void *value) {
    if (H5Aexists_by_name(file_, group.c_str(), name, H5P_DEFAULT) <= 0)
      return false;
    Handle attr(H5Aopen_by_name(file_, group.c_str(), name, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    return attr.valid() && H5Aread(attr, type, value) >= 0;
  }

  /// The file to continue is not the series of the checkpoint: it is left as
  /// it is (every rank is here: closing is collective).
  [[noreturn]] void refuse(const std::string &why) {
    const hid_t file = std::exchange(file_, -1);
    if (file >= 0)
      H5Fclose(file);
    if (continued_ == path_)
      removePartial(); // the copy
    throw RunError("cannot continue '" + continued_ + "' after the checkpoint: " + why +
                   "; it is left as it was: move it away, or restart into another --out");
  }

  void removePartial() {
    if (rankOf() != 0)
      return;
    std::error_code ec;
    std::filesystem::remove(partial_, ec);
  }

  /// A failed write leaves the file in no state a reader can trust (the
  /// step being written is half there): it is closed and removed, like a
  /// frame that could not be written whole.
  [[noreturn]] void fail(const std::string &what) {
    const int error = errno;
    const std::string cause = error ? std::string(": ") + std::strerror(error) : std::string();
    const hid_t file = std::exchange(file_, -1);
    // Parallel: closing is collective, and the other ranks may not be here;
    // the job is ended (MPI_Abort) once this error reaches the entry point.
    if (file >= 0 && !parallel) {
      // Every object of the file first (the group and dataset being
      // written): closing them after the file makes HDF5 crash at exit.
      const ssize_t open = H5Fget_obj_count(file, H5F_OBJ_ALL | H5F_OBJ_LOCAL);
      std::vector<hid_t> ids(open > 0 ? std::size_t(open) : 0);
      if (!ids.empty())
        H5Fget_obj_ids(file, H5F_OBJ_ALL | H5F_OBJ_LOCAL, ids.size(), ids.data());
      for (hid_t id : ids)
        if (id != file)
          H5Oclose(id);
      H5Fclose(file);
    }
    // Every rank that fails removes it: the first to fail may be any rank,
    // and the job may end (MPI_Abort) before another gets here.
    std::error_code ec;
    std::filesystem::remove(partial_, ec);
    const std::string left =
        ec ? " (the partial file '" + partial_ + "' could not be removed: " + ec.message() + ")"
           : " (the partial file was removed)";
    throw RunError("error while writing '" + path_ + "': HDF5 could not " + what + cause + left);
  }

  std::string path_, partial_;
  std::string continued_ = path_; ///< a restart's earlier file
  hid_t file_ = -1;
  std::uint64_t frames_ = 0;
};

} // namespace

#ifdef WASH_HDF5_PARALLEL
std::unique_ptr<Hdf5Series> openParallelHdf5Series(const std::string &path,
                                                   const std::string &partial,
                                                   const std::vector<Hdf5Step> &keep) {
  return std::make_unique<H5PartSeries>(path, partial, keep);
}
#else
std::unique_ptr<Hdf5Series> openSerialHdf5Series(const std::string &path,
                                                 const std::string &partial,
                                                 const std::vector<Hdf5Step> &keep) {
  return std::make_unique<H5PartSeries>(path, partial, keep);
}
#endif

} // namespace wash::detail
