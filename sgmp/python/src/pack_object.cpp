// The Python `sgmp.Pack`: a pack's particles as read-only numpy arrays (copies), its header
// as a dict of strings in header order (typed by sgmp/__init__.py), and pickling.
#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "bindings.hpp"
#include "sgmp/pack/header_entry.hpp"

namespace sgmp::python {
namespace {

/// Marks an array read-only: an assignment into it raises ValueError instead of changing a
/// copy that nothing reads (the pack itself is immutable from Python).
template <class Array>
Array frozen(Array array) {
    array.attr("flags").attr("writeable") = false;
    return array;
}

py::array_t<double> positions(const Pack& pack) {
    const auto n = static_cast<py::ssize_t>(pack.particles.size());
    py::array_t<double> out({n, py::ssize_t{3}});
    auto view = out.mutable_unchecked<2>();
    for (py::ssize_t i = 0; i < n; ++i) {
        const Vec3& c = pack.particles[static_cast<std::size_t>(i)].center;
        for (py::ssize_t k = 0; k < 3; ++k) {
            view(i, k) = c[k];
        }
    }
    return frozen(out);
}

template <class T, class Get>
py::array_t<T> column(const Pack& pack, Get get) {
    py::array_t<T> out(static_cast<py::ssize_t>(pack.particles.size()));
    auto view = out.template mutable_unchecked<1>();
    for (std::size_t i = 0; i < pack.particles.size(); ++i) {
        view(static_cast<py::ssize_t>(i)) = get(pack.particles[i]);
    }
    return frozen(out);
}

py::dict header(const Pack& pack) {
    py::dict out;
    for (const auto& [key, value] : pack.metadata.entries()) {
        out[py::str(key)] = value;
    }
    return out;
}

using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;
using Longs = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;

/// `values` as a float array, refusing what a float cannot hold without loss of meaning
/// (complex numbers, strings, objects) instead of casting it silently.
Doubles real_array(const py::object& object, const char* name) {
    const py::array values = py::array::ensure(object);
    if (!values) {
        throw std::invalid_argument(std::string(name) + ": must be an array of numbers");
    }
    const char kind = values.dtype().kind();
    if (kind != 'f' && kind != 'i' && kind != 'u' && kind != 'b') {
        throw std::invalid_argument(std::string(name) + ": must be real numbers (dtype " +
                                    py::str(values.dtype()).cast<std::string>() + ")");
    }
    return Doubles::ensure(values);
}

/// `object` as whole numbers, or none when it is None. Integer arrays pass; real arrays only
/// when every entry is a finite whole number within int64 (NaN became INT64_MIN and 2.7 was
/// truncated to 2, silently); anything else is refused naming the entry.
std::optional<Longs> whole_array(const py::object& object, const char* name) {
    if (object.is_none()) {
        return std::nullopt;
    }
    const py::array values = py::array::ensure(object);
    if (!values) {
        throw std::invalid_argument(std::string(name) + ": must be an array of whole numbers");
    }
    const char kind = values.dtype().kind();
    if (kind == 'i' || kind == 'u' || kind == 'b') {
        return Longs::ensure(values);
    }
    if (kind != 'f') {
        throw std::invalid_argument(std::string(name) + ": must be whole numbers (dtype " +
                                    py::str(values.dtype()).cast<std::string>() + ")");
    }
    const Doubles reals = Doubles::ensure(values);
    const double* data = reals.data();
    for (py::ssize_t i = 0; i < reals.size(); ++i) {
        const double v = data[i];
        if (!std::isfinite(v) || v != std::floor(v) || std::fabs(v) >= 9.2e18) {
            throw std::invalid_argument(std::string(name) + ": entry " + std::to_string(i) + " = " +
                                        format_number(v) + " must be a whole number");
        }
    }
    return Longs::ensure(values);
}

/// The header's entries as strings; a key or value that is not a string is refused (its
/// str() would not read back as the same thing).
py::dict string_header(const std::optional<py::dict>& head) {
    if (!head) {
        return {};
    }
    for (const auto& [key, value] : *head) {
        if (!py::isinstance<py::str>(key)) {
            throw std::invalid_argument("header: key " + py::repr(key).cast<std::string>() +
                                        " must be a string");
        }
    }
    return *head;
}

Pack make(const py::object& xyz_in, const py::object& radii_in, const py::object& bins_in,
          const py::object& ids_in, const std::optional<py::dict>& head,
          const py::object& species_in) {
    const Doubles xyz = real_array(xyz_in, "positions");
    const Doubles radii = real_array(radii_in, "radii");
    const std::optional<Longs> bins = whole_array(bins_in, "bins");
    const std::optional<Longs> ids = whole_array(ids_in, "ids");
    const std::optional<Longs> species = whole_array(species_in, "species");
    if (xyz.ndim() != 2 || xyz.shape(1) != 3) {
        throw std::invalid_argument("positions: must be an array of shape (N, 3)");
    }
    const py::ssize_t n = xyz.shape(0);
    auto same_length = [n](const auto& a, const char* name) {
        if (a.ndim() != 1 || a.shape(0) != n) {
            throw std::invalid_argument(
                std::string(name) + ": must be an array of shape (N,), N = " + std::to_string(n) +
                " as the positions");
        }
    };
    same_length(radii, "radii");
    if (bins) {
        same_length(*bins, "bins");
    }
    if (ids) {
        same_length(*ids, "ids");
    }
    if (species) {
        same_length(*species, "species");
    }
    Pack pack;
    const auto p = xyz.unchecked<2>();
    const auto r = radii.unchecked<1>();
    for (py::ssize_t i = 0; i < n; ++i) {
        Particle particle;
        particle.id = ids ? ids->at(i) : static_cast<std::int64_t>(i + 1);
        particle.center = Vec3(p(i, 0), p(i, 1), p(i, 2));
        particle.radius = r(i);
        if (!particle.center.allFinite()) {
            throw std::invalid_argument("positions: row " + std::to_string(i) +
                                        " is not finite (every coordinate must be a number)");
        }
        if (!(particle.radius > 0.0) || !std::isfinite(particle.radius)) {
            throw std::invalid_argument("radii: entry " + std::to_string(i) + " = " +
                                        format_number(particle.radius) +
                                        " must be a finite number > 0");
        }
        if (bins) {
            const std::int64_t bin = bins->at(i);
            if (bin < 0 || bin > std::numeric_limits<int>::max()) {
                throw std::invalid_argument("bins: entry " + std::to_string(i) + " = " +
                                            std::to_string(bin) + " must be from 0 to " +
                                            std::to_string(std::numeric_limits<int>::max()));
            }
            particle.color = static_cast<int>(bin);
        }
        if (species) {
            const std::int64_t s = species->at(i);
            if (s < 0 || s > kMaxSpecies) {
                throw std::invalid_argument("species: entry " + std::to_string(i) + " = " +
                                            std::to_string(s) + " must be from 0 to " +
                                            std::to_string(kMaxSpecies));
            }
            particle.species = static_cast<int>(s);
        }
        pack.particles.push_back(particle);
    }
    for (const auto& [key, value] : string_header(head)) {
        const std::string text = py::str(value).cast<std::string>();
        check_header_entry(key.cast<std::string>(), text);
        pack.metadata.set(key.cast<std::string>(), text);
    }
    return pack;
}

/// The state pickle keeps: the arrays and the header's (key, value) pairs in order.
py::tuple state_of(const Pack& p) {
    py::list header_items;
    for (const auto& [key, value] : p.metadata.entries()) {
        header_items.append(py::make_tuple(key, value));
    }
    return py::make_tuple(
        positions(p), column<double>(p, [](auto& q) { return q.radius; }),
        column<std::int64_t>(p, [](auto& q) { return q.color; }),
        column<std::int64_t>(p, [](auto& q) { return q.id; }), header_items,
        column<std::int64_t>(p, [](auto& q) { return static_cast<std::int64_t>(q.species); }));
}

Pack from_state(const py::tuple& state) {
    if (state.size() != 6) {
        throw std::invalid_argument("an sgmp.Pack state has 6 fields");
    }
    py::dict header;
    for (const auto& item : state[4].cast<py::list>()) {
        const auto pair = item.cast<py::tuple>();
        header[pair[0]] = pair[1];
    }
    return make(state[0], state[1], state[2], state[3], header, state[5]);
}

}  // namespace

const Pack& pack_of(const py::handle& object) {
    try {
        return object.cast<const Pack&>();
    } catch (const py::cast_error&) {
        throw std::invalid_argument(
            "pack: must be an sgmp.Pack (from sgmp.pack, sgmp.read or "
            "sgmp.Pack(positions, radii, ...))");
    }
}

void bind_pack(py::module_& m) {
    py::class_<Pack>(m, "Pack",
                     "A pack: positions (N, 3), radii (N,), bins (N,) colour labels 0-9, ids "
                     "(N,), species (N,) (0 for a pack of one species) and its header. The "
                     "arrays are read-only copies; header_text holds the header's key=value "
                     "pairs as strings, header (sgmp/__init__.py) the same typed.")
        .def(py::init(&make), py::arg("positions"), py::arg("radii"), py::arg("bins") = py::none(),
             py::arg("ids") = py::none(), py::arg("header") = py::none(),
             py::arg("species") = py::none(),
             "A pack from arrays; ids default to 1..N, bins and species to 0, the header to "
             "empty.")
        .def_property_readonly("positions", &positions, "centres, shape (N, 3), read-only")
        .def_property_readonly(
            "radii",
            [](const Pack& p) { return column<double>(p, [](auto& q) { return q.radius; }); },
            "radii, shape (N,), read-only")
        .def_property_readonly(
            "bins",
            [](const Pack& p) { return column<std::int64_t>(p, [](auto& q) { return q.color; }); },
            "colour bins, shape (N,), read-only")
        .def_property_readonly(
            "ids",
            [](const Pack& p) { return column<std::int64_t>(p, [](auto& q) { return q.id; }); },
            "particle ids, shape (N,), read-only")
        .def_property_readonly(
            "species",
            [](const Pack& p) {
                return column<std::int64_t>(
                    p, [](auto& q) { return static_cast<std::int64_t>(q.species); });
            },
            "species 1... of a blend (0 for a pack of one species), shape (N,), read-only")
        .def_property_readonly("header_text", &header,
                               "the header's key=value pairs as strings, in order")
        .def("__len__", [](const Pack& p) { return p.particles.size(); })
        .def("__repr__",
             [](const Pack& p) {
                 const auto generator = p.metadata.get("generator");
                 return "<sgmp.Pack of " + std::to_string(p.particles.size()) + " particles" +
                        (generator ? ", generator=" + *generator : std::string()) + ">";
             })
        .def(py::pickle(&state_of, &from_state));
}

}  // namespace sgmp::python
