#pragma once
// Lab-frame cells of side >= d (so any touching pair sits in adjacent cells), each holding its
// particles in a fixed-size block of slots, newest first. A block holds a few particles (a
// cell is narrower than 2d, so at most 8 disks that do not overlap), so insert and remove
// shift a handful of slots, and a cell's members are read as one contiguous span: walking
// them costs no pointer chase and no unpredictable loop exit per particle, as a linked list
// did (docs/performance.md, "Cells as blocks of slots"). Blocks start with room for 3; one
// that would overflow doubles the room of every block.
// Periodic directions wrap; the neighbour stencil then carries the image shift to apply to
// the partner.
#include <span>
#include <vector>

namespace granwave {

struct CellGeometry {
  int nx = 1, nz = 1;
  double x0 = 0, z0 = 0;  // lower-left corner of the grid
  double wx = 1, wz = 1;  // cell sizes
  bool periodic_x = false, periodic_z = false;
  double lx() const { return nx * wx; }
  double lz() const { return nz * wz; }
};

// Side length of at least `min_side`, dividing `length` into a whole number of cells.
int cellsAlong(double length, double min_side);

class CellGrid {
 public:
  CellGrid() = default;
  explicit CellGrid(const CellGeometry& g, int particles);

  const CellGeometry& geometry() const { return g_; }
  int index(int cx, int cz) const { return cz * g_.nx + cx; }
  int cx(int cell) const { return cell % g_.nx; }
  int cz(int cell) const { return cell / g_.nx; }
  // Cell containing point (x, z), clamped into the grid.
  int locate(double x, double z) const;

  // `particle` becomes the first member of `cell`.
  void insert(int particle, int cell);
  void remove(int particle);
  int cellOf(int particle) const { return cell_[particle]; }
  // The particles in `cell`, the most recently inserted first.
  std::span<const int> members(int cell) const {
    const int* block = &slots_[static_cast<std::size_t>(cell) * stride_];
    return {block + 1, static_cast<std::size_t>(block[0])};
  }
  // Capacity of a block: a cell never holds more particles than this.
  int capacity() const { return stride_ - 1; }

  double xLow(int cell) const { return g_.x0 + cx(cell) * g_.wx; }
  double zLow(int cell) const { return g_.z0 + cz(cell) * g_.wz; }

  // Neighbour stencil (3 x 3, self included): cell index and the shift to add to a partner's
  // position so that it is the image nearest to the centre cell. Cells outside a
  // non-periodic grid are left out.
  struct Neighbour {
    int cell;
    double shift_x, shift_z;
  };
  int neighbours(int cell, Neighbour out[9]) const;
  // The part of that stencil that a particle entering `cell` by a step (step_x, step_z) (one
  // of them +-1, the other 0) did not have before: the row or column on the far side.
  int newNeighbours(int cell, int step_x, int step_z, Neighbour out[3]) const;

  // The members of every cell, in order, written as doubly linked lists (the checkpoint's
  // layout): the order of particles in a cell is the order pairs are predicted in, which
  // decides between pair events at exactly equal times (lattice starts); a restart keeps it
  // rather than rebuilding the cells.
  struct Lists {
    std::vector<int> head, next, prev, cell;
  };
  Lists lists() const;
  // std::invalid_argument unless `saved` fits this grid and its particle count and every
  // particle is linked into the cell it names.
  void restore(const Lists& saved);

 private:
  void grow();

  CellGeometry g_;
  // Block of cell c: slots_[c * stride_] is its member count, the next stride_ - 1 slots its
  // members, newest first.
  int stride_ = 4;
  std::vector<int> slots_;
  std::vector<int> cell_;
};

}  // namespace granwave
