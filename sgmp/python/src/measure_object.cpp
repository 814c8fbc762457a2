// sgmp.measure(pack, ...): every metric of one pack (compare/README.md) as the dict of
// `sgmp-compare measure`'s metrics.json, plus the curves as numpy arrays. Options are the
// metrics library's MeasureOptions, defaults taken from the struct itself.
#include <pybind11/stl.h>

#include <stdexcept>

#include "bindings.hpp"
#include "sgmp/metrics/measure.hpp"
#include "sgmp/metrics/metric_descriptors.hpp"
#include "sgmp/metrics/metrics_output.hpp"
#include "sgmp/metrics/parallel.hpp"
#include "sgmp/pack/parameter_error.hpp"

namespace sgmp::python {
namespace {

using metrics::Measurement;
using metrics::MeasureOptions;

/// Columns `columns` of equal length as one (rows, columns) array.
py::array_t<double> table(const std::vector<const std::vector<double>*>& columns) {
    const std::size_t rows = columns.empty() ? 0 : columns.front()->size();
    py::array_t<double> out(
        {static_cast<py::ssize_t>(rows), static_cast<py::ssize_t>(columns.size())});
    auto view = out.mutable_unchecked<2>();
    for (std::size_t c = 0; c < columns.size(); ++c) {
        for (std::size_t r = 0; r < rows; ++r) {
            view(static_cast<py::ssize_t>(r), static_cast<py::ssize_t>(c)) = (*columns[c])[r];
        }
    }
    return out;
}

/// P(Z) as rows z = 0, 1, ...: the column z, then one column per tolerance (zero-padded).
py::array_t<double> p_z(const Measurement& m) {
    const auto& c = m.local.coordination;
    std::size_t rows = 0;
    for (const auto& p : c.p_z) {
        rows = std::max(rows, p.size());
    }
    std::vector<std::vector<double>> columns(c.tolerances.size() + 1,
                                             std::vector<double>(rows, 0.0));
    for (std::size_t z = 0; z < rows; ++z) {
        columns[0][z] = static_cast<double>(z);
        for (std::size_t t = 0; t < c.tolerances.size(); ++t) {
            columns[t + 1][z] = z < c.p_z[t].size() ? c.p_z[t][z] : 0.0;
        }
    }
    std::vector<const std::vector<double>*> pointers;
    for (const auto& column : columns) {
        pointers.push_back(&column);
    }
    return table(pointers);
}

py::dict measure(const py::object& pack_object, const std::optional<std::vector<double>>& region,
                 double slab, double gr_bin, double gr_range, const std::string& gr_density,
                 bool gr_container_space, bool voronoi, double q6_cutoff, double overlap_floor,
                 unsigned threads) {
    const Pack& pack = pack_of(pack_object);
    MeasureOptions o;
    if (region) {
        if (region->size() != 6) {
            throw ParameterError("region", std::to_string(region->size()) + " numbers",
                                 "must be six numbers xlo xhi ylo yhi zlo zhi (length units)");
        }
        const auto& b = *region;
        o.region = Box{Vec3(b[0], b[2], b[4]), Vec3(b[1], b[3], b[5])};
    }
    o.slab_thickness = slab;
    o.gr_bin_width = gr_bin;
    o.gr_range = gr_range;
    if (gr_density != "neighbours" && gr_density != "space") {
        throw ParameterError("gr_density", gr_density, "must be one of neighbours, space");
    }
    o.gr_density =
        gr_density == "space" ? metrics::RdfDensity::Space : metrics::RdfDensity::Neighbours;
    o.gr_container_space = gr_container_space;
    o.voronoi = voronoi;
    o.q6_cutoff = q6_cutoff;
    o.overlap_floor = overlap_floor;
    if (threads > 256) {
        throw ParameterError("threads", std::to_string(threads),
                             "must be in [0, 256] (0: all cores)");
    }
    o.threads = threads;
    metrics::validate(o);
    Measurement m;
    {
        py::gil_scoped_release unlocked;
        m = metrics::measure(pack, o);
    }
    const auto json = metrics::metrics_json(m, metrics::provenance("python", pack, o));
    py::dict out = py::module_::import("json").attr("loads")(json.dump());
    const auto& rdf = m.local.rdf;
    out[metrics::metric_with(metrics::MetricRole::PairCorrelation).name.c_str()] =
        table({&rdf.r_over_d, &rdf.g});
    std::vector<double> y_mid;
    for (std::size_t k = 0; k < m.phi_profile.phi.size(); ++k) {
        y_mid.push_back(0.5 * (m.phi_profile.y_lo[k] + m.phi_profile.y_hi[k]));
    }
    out["phi_y"] = table({&y_mid, &m.phi_profile.phi});
    if (m.species) {  // a blend: g_r.csv's g_I_J and phi_y.csv's phi_I, on their own centres
        py::dict partial;
        for (const metrics::SpeciesPair& pair : m.species->pairs) {
            std::vector<double> r(rdf.r_over_d.size());
            for (std::size_t k = 0; k < r.size(); ++k) {
                r[k] = rdf.r_over_d[k] + pair.bin_offset_over_d;
            }
            const std::string name = "g_" + std::to_string(pair.i) + "_" + std::to_string(pair.j);
            partial[name.c_str()] = table({&r, &pair.g});
        }
        out["g_r_partial"] = partial;
    }
    if (!m.phi_profile_by_species.empty()) {
        py::dict by_species;
        for (const auto& profile : m.phi_profile_by_species) {
            const std::string name = "phi_" + std::to_string(profile.species);
            by_species[name.c_str()] = table({&y_mid, &profile.phi});
        }
        out["phi_y_species"] = by_species;
    }
    out["p_z"] = p_z(m);
    out["p_z_tolerances"] = metrics::coordination_tolerance_names();
    return out;
}

/// The metric table (metric_descriptors.hpp), one dict per metric.
py::list metric_table() {
    py::list out;
    for (const metrics::MetricDescriptor& d : metrics::metric_descriptors()) {
        const char* kind = d.kind == metrics::MetricKind::Scalar  ? "scalar"
                           : d.kind == metrics::MetricKind::Curve ? "curve"
                                                                  : "distribution";
        py::dict one;
        one["name"] = d.name;
        one["label"] = d.label;
        one["unit"] = d.unit;
        one["definition"] = d.definition;
        one["kind"] = kind;
        one["margin"] = d.margin;
        one["judged"] = d.judged;
        one["contact_tolerance"] =
            d.contact_tolerance ? py::object(py::float_(*d.contact_tolerance)) : py::none();
        one["summary_column"] = d.summary_column.empty() ? py::object(py::none())
                                                         : py::object(py::str(d.summary_column));
        one["in_report"] = d.report;
        one["in_metrics_json"] = d.json_rank != metrics::kUnranked;
        out.append(one);
    }
    return out;
}

}  // namespace

void bind_measure(py::module_& m) {
    m.def("metric_table", &metric_table,
          "The metric table: one dict per metric (name, label, unit, definition link, kind "
          "scalar/curve/distribution, margin, judged, contact_tolerance, summary_column, "
          "in_report, in_metrics_json), as sgmp-compare judges and writes them.");
    const MeasureOptions defaults;
    m.def("measure", &measure, py::arg("pack"), py::arg("region") = py::none(),
          py::arg("slab") = defaults.slab_thickness, py::arg("gr_bin") = defaults.gr_bin_width,
          py::arg("gr_range") = defaults.gr_range, py::arg("gr_density") = "neighbours",
          py::arg("gr_container_space") = defaults.gr_container_space,
          py::arg("voronoi") = defaults.voronoi, py::arg("q6_cutoff") = defaults.q6_cutoff,
          py::arg("overlap_floor") = defaults.overlap_floor, py::arg("threads") = 0U,
          "Every metric of one pack, as `sgmp-compare measure` (options named as its "
          "command-line options, dashes as underscores; region = [xlo, xhi, ylo, yhi, zlo, "
          "zhi], default the control volume). Returns the dict of its metrics.json (phi, "
          "overlaps, z_mean_tol_*, split_ratio, q6_*, voronoi_phi_*, ...) plus the curves as "
          "numpy arrays: g_r (rows r/d, g), phi_y (rows y_mid, phi), p_z (rows z, then P(Z) "
          "at each tolerance of p_z_tolerances); for a blend also g_r_partial (per pair type "
          "'g_I_J', I <= J: rows r/d at that pair type's bin centres, g_IJ) and phi_y_species "
          "(per species 'phi_I': rows y_mid, phi_I).");
}

}  // namespace sgmp::python
