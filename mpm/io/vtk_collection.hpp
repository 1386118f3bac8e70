/// \file
/// Snapshots as a ParaView time series: each snapshot as a VTK XML PolyData file (snapshot_NNNN.vtp)
/// and one collection, snapshots.pvd, listing every file with its physical time. ParaView reads a
/// .pvd's DataSets only in the XML formats (its collection reader picks the reader by the extension
/// .vtp, .vtu, ...). The collection is
/// a VTKFile of type "Collection" with one DataSet element per snapshot, whose attributes are the
/// physical time (`timestep="0.0001"`) and the file (`file="snapshot_0001.vtp"`).
#pragma once
#include <iomanip>
#include <string>
#include <utility>
#include <vector>

#include "mpm/io/output_file.hpp"
#include "mpm/particles/particles.hpp"

namespace mpm::io {

/// Writes every particle as a vertex of a VTK XML PolyData file (ASCII), with its velocity, stress
/// (3x3, plane strain sigma_zz included), density and id. \throws OutputFailure if it cannot be written.
template <int Dim>
void write_vtp(const std::string& path, const Particles<Dim>& particles) {
  OutputFile out(path, OutputFile::Mode::atomic);  // whole or absent, even when the disk fills
  const int count = particles.size();
  out << std::setprecision(12) << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n<PolyData>\n"
      << "<Piece NumberOfPoints=\"" << count << "\" NumberOfVerts=\"" << count
      << "\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
      << "<PointData Vectors=\"velocity\" Tensors=\"stress\" Scalars=\"density\">\n"
      << "<DataArray type=\"Float64\" Name=\"velocity\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (int p = 0; p < count; ++p) {
    const auto& v = particles.velocity[p];
    out << v[0] << " " << (Dim == 2 ? v[Dim - 1] : 0.0) << " 0\n";
  }
  out << "</DataArray>\n<DataArray type=\"Float64\" Name=\"stress\" NumberOfComponents=\"9\" format=\"ascii\">\n";
  for (int p = 0; p < count; ++p) {
    const auto& s = particles.stress[p];
    const double xy = Dim == 2 ? s(0, Dim - 1) : 0.0, yy = Dim == 2 ? s(Dim - 1, Dim - 1) : 0.0;
    out << s(0, 0) << " " << xy << " 0 " << xy << " " << yy << " 0 0 0 " << particles.stress_zz[p] << "\n";
  }
  out << "</DataArray>\n<DataArray type=\"Float64\" Name=\"density\" format=\"ascii\">\n";
  for (int p = 0; p < count; ++p) out << particles.density[p] << "\n";
  out << "</DataArray>\n<DataArray type=\"Int32\" Name=\"id\" format=\"ascii\">\n";
  for (int p = 0; p < count; ++p) out << particles.id[p] << "\n";
  out << "</DataArray>\n</PointData>\n<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (int p = 0; p < count; ++p) {
    const auto& x = particles.position[p];
    out << x[0] << " " << (Dim == 2 ? x[Dim - 1] : 0.0) << " 0\n";
  }
  out << "</DataArray>\n</Points>\n<Verts>\n<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">\n";
  for (int p = 0; p < count; ++p) out << p << "\n";
  out << "</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">\n";
  for (int p = 0; p < count; ++p) out << p + 1 << "\n";
  out << "</DataArray>\n</Verts>\n</Piece>\n</PolyData>\n</VTKFile>\n";
  out.close();
}

/// The .pvd collection of a run's snapshots. It is rewritten whole (atomically) after every snapshot, so a
/// run that fails or is stopped half-way leaves a valid collection of what it wrote.
class PvdCollection {
 public:
  explicit PvdCollection(std::string path) : path_(std::move(path)) {}

  /// Adds `file` (relative to the .pvd's folder) at physical time `time` and rewrites the collection.
  /// \throws OutputFailure if it cannot be written.
  void add(double time, const std::string& file) {
    entries_.emplace_back(time, file);
    OutputFile out(path_, OutputFile::Mode::atomic);
    out << std::setprecision(17) << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n<Collection>\n";
    for (const auto& [entry_time, entry_file] : entries_)
      out << "  <DataSet timestep=\"" << entry_time << "\" group=\"\" part=\"0\" file=\"" << entry_file << "\"/>\n";
    out << "</Collection>\n</VTKFile>\n";
    out.close();
  }

 private:
  std::string path_;
  std::vector<std::pair<double, std::string>> entries_;
};

}  // namespace mpm::io
