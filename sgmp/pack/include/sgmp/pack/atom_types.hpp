#pragma once
/// @file atom_types.hpp
/// Atom types for formats that have them (LAMMPS data and dump files): the size mode of
/// each sphere. With `size_modes="a1:f1,a2:f2,..."` and `diameter=D` in the header, sphere
/// i has type 1 + argmin_k |2 r_i − a_k D| (modes in the listed order; ties to the first);
/// without them every type is 1.

#include <vector>

#include "sgmp/pack/pack.hpp"

namespace sgmp {

/// The type of every particle, in order, and how many types there are (at least 1).
struct AtomTypes {
    std::vector<int> type;
    int count = 1;
};

AtomTypes atom_types(const Pack& pack);

}  // namespace sgmp
