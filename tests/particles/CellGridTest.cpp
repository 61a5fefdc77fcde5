// The cell grid against a trivially correct reference (a vector per cell, newest first): the
// members of a cell and their order decide the order pairs are predicted in, so both must
// survive inserts, removes, blocks that overflow and grow, and a checkpoint round trip.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <stdexcept>
#include <vector>

#include "particles/CellGrid.hpp"

namespace {

using granwave::CellGeometry;
using granwave::CellGrid;

CellGeometry smallGrid() {
  CellGeometry g;
  g.nx = 3;
  g.nz = 2;
  return g;
}

void expectSameMembers(const CellGrid& grid, const std::vector<std::vector<int>>& ref) {
  for (std::size_t c = 0; c < ref.size(); ++c) {
    const auto m = grid.members(static_cast<int>(c));
    ASSERT_EQ(std::vector<int>(m.begin(), m.end()), ref[c]) << "cell " << c;
  }
}

}  // namespace

TEST(CellGrid, MembersMatchReferenceUnderRandomInsertsAndRemoves) {
  const int n = 40, cells = 6;
  CellGrid grid(smallGrid(), n);
  std::vector<std::vector<int>> ref(cells);
  std::vector<int> where(n, -1);
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int> pick(0, n - 1), cell(0, cells - 1);
  for (int step = 0; step < 5000; ++step) {
    const int p = pick(rng);
    if (where[p] >= 0) {
      grid.remove(p);
      auto& r = ref[where[p]];
      r.erase(std::find(r.begin(), r.end(), p));
      where[p] = -1;
    } else {
      where[p] = cell(rng);
      grid.insert(p, where[p]);
      ref[where[p]].insert(ref[where[p]].begin(), p);
    }
    ASSERT_EQ(grid.cellOf(p), where[p]);
    expectSameMembers(grid, ref);
  }
}

TEST(CellGrid, CellHoldingMoreThanABlockGrowsAndKeepsOrder) {
  CellGrid grid(smallGrid(), 20);
  const int before = grid.capacity();
  for (int p = 0; p < 20; ++p) grid.insert(p, p % 2 == 0 ? 4 : 1);
  EXPECT_GE(grid.capacity(), 10);
  EXPECT_GT(grid.capacity(), before);
  std::vector<std::vector<int>> ref(6);
  for (int p = 19; p >= 0; --p) ref[p % 2 == 0 ? 4 : 1].push_back(p);
  expectSameMembers(grid, ref);
}

TEST(CellGrid, ListsRestoredIntoAFreshGridGiveTheSameMembersInOrder) {
  CellGrid grid(smallGrid(), 12);
  std::vector<std::vector<int>> ref(6);
  for (int p = 0; p < 12; ++p) {
    const int c = (p * 5) % 6;
    grid.insert(p, c);
    ref[c].insert(ref[c].begin(), p);
  }
  grid.remove(5);  // particle 5 sits in cell (5 * 5) % 6 = 1
  ref[1].erase(std::find(ref[1].begin(), ref[1].end(), 5));
  grid.insert(5, 0);
  ref[0].insert(ref[0].begin(), 5);
  CellGrid copy(smallGrid(), 12);
  copy.restore(grid.lists());
  expectSameMembers(copy, ref);
  const auto a = grid.lists(), b = copy.lists();
  EXPECT_EQ(a.head, b.head);
  EXPECT_EQ(a.next, b.next);
  EXPECT_EQ(a.prev, b.prev);
  EXPECT_EQ(a.cell, b.cell);
}

TEST(CellGrid, RestoreRefusesListsThatLeaveAParticleOut) {
  CellGrid grid(smallGrid(), 3);
  grid.insert(0, 0);
  grid.insert(1, 2);
  grid.insert(2, 2);
  auto lists = grid.lists();
  lists.head[2] = lists.next[lists.head[2]];  // drop the first member of cell 2
  lists.prev[lists.head[2]] = -1;
  CellGrid copy(smallGrid(), 3);
  EXPECT_THROW(copy.restore(lists), std::invalid_argument);
}
