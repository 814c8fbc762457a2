// The "definitions" of metrics.json (metric_descriptors.hpp): the text of each key.
#include "sgmp/metrics/metric_descriptors.hpp"

namespace sgmp::metrics {

const std::vector<std::pair<std::string, std::string>>& metric_definitions() {
    static const std::vector<std::pair<std::string, std::string>> texts{

        {"diameter", "mean diameter d = 2<r>; the length unit of every *_over_d value and of g(r)"},
        {"phi", "exact sphere volume inside the region / region volume"},
        {"overlaps", "pairs of the whole pack with r_i + r_j - |c_i - c_j| > overlap_floor*d"},
        {"overlaps_any", "pairs of the whole pack with any positive overlap"},
        {"z_mean_tol_X",
         "mean number of particles j with |c_i-c_j| - r_i - r_j <= X*d, over centres i in the "
         "region (walls apart)"},
        {"wall_contacts_tol_X", "wall and floor contacts of centres in the region at gap <= X*d"},
        {"split_ratio",
         "g(sqrt(3) d) / g(2 d): mean g in the windows |r - sqrt(3) d| <= 0.05 d and |r - 2 d| "
         "<= 0.05 d, each from its pair count over its edge-corrected window volume"},
        {"voronoi_phi",
         "local packing fraction (4/3 pi r^3) / V_cell of the centres in the region, cells of the "
         "Voronoi (radical for unequal radii) tessellation bounded by the container walls, the "
         "floor and a lid one diameter above the top sphere (voro++); sd over cells (population)"},
        {"q6", "Steinhardt Q6, bonds |c_i-c_j| <= q6_cutoff*(r_i + r_j), origins in the region"},
        {"g_r",
         "origins: centres in the region; neighbours: all particles; shells counted inside the "
         "space (default: container shrunk by d/2 at walls and floor, up to the highest centre; "
         "gr_space=container: the container up to the top sphere); bins centred on k*bin_width; "
         "density (gr_density=neighbours) the pairs over the shell volume summed out to the "
         "range, so g -> 1 far from contact; gr_density=space: N/|space|"},
        {"size_distribution",
         "a polydisperse pack's radii by number: polydispersity sd(r)/mean(r), skewness "
         "<(r - mean)^3>/sd^3, and the random-close-packing fraction of frictionless spheres "
         "they predict by Desmond & Weeks, Phys. Rev. E 90, 022204 (2014): 0.634 + 0.0658 "
         "delta + 0.0857 S delta^2, null outside the formula's range (delta <= 0.4, "
         "-2 <= S <= 4)"},
        {"sides",
         "walls, or periodic: x and z periodic (pairs through every periodic image within "
         "reach: the nearest one for contacts, and every image within g(r)'s range, as in "
         "the infinite periodic pack, also beyond half the period; g(r) shells and Voronoi "
         "cells cut by the floor and the top alone; default region the whole cell across)"}};
    return texts;
}

}  // namespace sgmp::metrics
