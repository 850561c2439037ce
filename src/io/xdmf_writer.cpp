#include "io/xdmf_writer.hpp"

#include <fstream>
#include <sstream>

#include "io/format_number.hpp"
#include "io/hdf5_writer.hpp"
#include "io/output_error.hpp"

namespace colza {

namespace {

struct Item {
  const char* name;       // the dataset's name in its group
  const char* number;     // XDMF NumberType
  int precision;          // bytes
  std::size_t cols;       // values per row (1: a scalar)
};

// A dataset of single-precision vectors (3 a row) or scalars named `name`.
constexpr Item float3(const char* name) { return {name, "Float", 4, 3}; }
constexpr Item float1(const char* name) { return {name, "Float", 4, 1}; }

void data_item(std::ostream& x, const std::string& indent, const Item& item, std::size_t rows, const std::string& h5,
               const std::string& dataset) {
  x << indent << "<DataItem Dimensions=\"" << rows;
  if (item.cols > 1) x << ' ' << item.cols;
  x << "\" NumberType=\"" << item.number << "\" Precision=\"" << item.precision << "\" Format=\"HDF\">" << h5 << ':'
    << dataset << "</DataItem>\n";
}

void attribute(std::ostream& x, const Item& item, const char* center, std::size_t rows, const std::string& h5,
               const std::string& group) {
  x << "        <Attribute Name=\"" << item.name << "\" AttributeType=\"" << (item.cols == 3 ? "Vector" : "Scalar")
    << "\" Center=\"" << center << "\">\n";
  data_item(x, "          ", item, rows, h5, group + "/" + item.name);
  x << "        </Attribute>\n";
}

void time_and_geometry(std::ostream& x, const Snapshot& s, std::size_t points, const std::string& h5,
                       const std::string& dataset) {
  x << "        <Time Value=\"" << format_shortest(s.time) << "\"/>\n";
  x << "        <Geometry GeometryType=\"XYZ\">\n";
  data_item(x, "          ", float3(""), points, h5, dataset);
  x << "        </Geometry>\n";
}

void particles_grid(std::ostream& x, const Snapshot& s, const std::string& h5, const std::string& g) {
  const std::size_t n = s.particles();
  x << "      <Grid Name=\"particles\" GridType=\"Uniform\">\n";
  x << "        <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << n << "\" NodesPerElement=\"1\"/>\n";
  time_and_geometry(x, s, n, h5, g + "/position");
  for (const Item& item : {float1("radius"), float3("velocity"), float3("angular_velocity"), float3("force"),
                           Item{"coordination", "Int", 4, 1}})
    attribute(x, item, "Node", n, h5, g);
  x << "      </Grid>\n";
}

void contacts_grid(std::ostream& x, const Snapshot& s, const std::string& h5, const std::string& g) {
  const std::size_t m = s.contacts();
  x << "      <Grid Name=\"contacts\" GridType=\"Uniform\">\n";
  x << "        <Topology TopologyType=\"Polyline\" NumberOfElements=\"" << m << "\" NodesPerElement=\"2\">\n";
  data_item(x, "          ", Item{"pairs", "Int", 4, 2}, m, h5, g + "/contacts/pairs");
  x << "        </Topology>\n";
  time_and_geometry(x, s, s.particles(), h5, g + "/position");
  for (const Item& item : {float1("normal_force"), float3("shear_force"), Item{"bonded", "UChar", 1, 1}})
    attribute(x, item, "Cell", m, h5, g + "/contacts");
  x << "      </Grid>\n";
}

void walls_grid(std::ostream& x, const Snapshot& s, const std::string& h5, const std::string& g) {
  const std::size_t q = s.quads();
  x << "      <Grid Name=\"walls\" GridType=\"Uniform\">\n";
  x << "        <Topology TopologyType=\"Quadrilateral\" NumberOfElements=\"" << q << "\">\n";
  data_item(x, "          ", Item{"quads", "Int", 4, 4}, q, h5, g + "/walls/quads");
  x << "        </Topology>\n";
  time_and_geometry(x, s, s.wall_point_count(), h5, g + "/walls/points");
  attribute(x, Item{"wall", "Int", 4, 1}, "Cell", q, h5, g + "/walls");
  attribute(x, float3("force"), "Cell", q, h5, g + "/walls");
  x << "      </Grid>\n";
}

}  // namespace

std::string xdmf_text(const SnapshotSeries& series, const std::string& h5) {
  std::ostringstream x;
  x << "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n<Xdmf Version=\"2.0\">\n  <Domain>\n";
  using GridWriter = void (*)(std::ostream&, const Snapshot&, const std::string&, const std::string&);
  const std::pair<const char*, GridWriter> collections[] = {
      {"particles", particles_grid}, {"contacts", contacts_grid}, {"walls", walls_grid}};
  for (const auto& [name, write_grid] : collections) {
    // An empty topology is not read by every XDMF reader: a grid without cells is left out,
    // and a collection without grids too.
    const auto has_cells = [&, name = std::string(name)](const Snapshot& s) {
      return (name == "contacts" ? s.contacts() : name == "walls" ? s.quads() : s.particles()) > 0;
    };
    std::ostringstream grids;
    for (std::size_t k = 0; k < series.snapshots.size(); ++k)
      if (has_cells(series.snapshots[k])) write_grid(grids, series.snapshots[k], h5, snapshot_group(k));
    if (grids.str().empty()) continue;
    x << "    <Grid Name=\"" << name << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n"
      << grids.str() << "    </Grid>\n";
  }
  x << "  </Domain>\n</Xdmf>\n";
  return x.str();
}

void write_xdmf(const std::string& file, const SnapshotSeries& series, const std::string& h5_name) {
  std::ofstream out(file, std::ios::binary);
  out << xdmf_text(series, h5_name);
  out.close();
  if (!out) throw_cannot_write(file);
}

}  // namespace colza
