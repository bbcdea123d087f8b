/* -*- c++ -*- ----------------------------------------------------------
   LAMMPS - Large-scale Atomic/Molecular Massively Parallel Simulator
   https://www.lammps.org/, Sandia National Laboratories
   LAMMPS development team: developers@lammps.org

   Copyright (2003) Sandia Corporation.  Under the terms of Contract
   DE-AC04-94AL85000 with Sandia Corporation, the U.S. Government retains
   certain rights in this software.  This software is distributed under
   the GNU General Public License.

   See the README file in the top-level LAMMPS directory.
------------------------------------------------------------------------- */

// Integer cell grid of cell size `size` anchored at the box origin; each cell holds its
// points in the order of (atom ID, position), so that sums over a cell's neighbourhood run
// in the same order on any number of ranks (images of one atom are told apart by position).
// Used by fix esph/boundary (the surface search) and by the touch of pair esph/solid (the
// cells of the particles).

#ifndef LMP_ESPH_GRID_H
#define LMP_ESPH_GRID_H

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <vector>

namespace ESPH {

struct CellGrid {
  const double *lo;
  double size;
  std::unordered_map<long long, std::vector<int>> cells;

  CellGrid(const double *lo_, double size_) : lo(lo_), size(size_) {}
  void cell_of(const double *x, long long *c) const
  {
    for (int d = 0; d < 3; d++) c[d] = (long long) floor((x[d] - lo[d]) / size) + (1 << 20);
  }
  static long long key_of(const long long *c) { return (c[0] << 42) | (c[1] << 21) | c[2]; }
  // the points of the cell c + (a, b, cc), or nullptr for an empty cell
  const std::vector<int> *at(const long long *c, int a, int b, int cc) const
  {
    const long long cm[3] = {c[0] + a, c[1] + b, c[2] + cc};
    auto it = cells.find(key_of(cm));
    return it == cells.end() ? nullptr : &it->second;
  }
  // n points, point k at pos(k) with atom ID tag(k)
  template <class Pos, class Tag> void build(int n, Pos pos, Tag tag)
  {
    std::vector<int> order(n);
    for (int k = 0; k < n; k++) order[k] = k;
    std::sort(order.begin(), order.end(), [&](int a, int b) {
      if (tag(a) != tag(b)) return tag(a) < tag(b);
      const double *p = pos(a), *q = pos(b);
      for (int d = 0; d < 3; d++)
        if (p[d] != q[d]) return p[d] < q[d];
      return false;
    });
    for (int k : order) {
      long long c[3];
      cell_of(pos(k), c);
      cells[key_of(c)].push_back(k);
    }
  }
};

}    // namespace ESPH

#endif
