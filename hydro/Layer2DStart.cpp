#include "hydro/Layer2DStart.hpp"

#include <cmath>
#include <random>
#include <stdexcept>

#include "hydro/SettledLayer.hpp"

namespace granwave::hydro {

std::vector<double> perturbedCellMasses(int columns, int cells, double column_mass,
                                        double amplitude, std::uint64_t seed) {
  std::vector<double> xi(columns, 0.0);
  if (amplitude != 0 && columns > 1) {
    std::mt19937_64 engine(seed);
    std::normal_distribution<double> normal;
    for (double& x : xi) {
      do x = normal(engine);
      while (std::abs(x) > 3);
    }
    double mean = 0, square = 0;
    for (double x : xi) mean += x / columns;
    for (double& x : xi) x -= mean, square += x * x / columns;
    for (double& x : xi) x /= std::sqrt(square);
  }
  std::vector<double> mu(static_cast<std::size_t>(columns) * cells);
  for (int i = 0; i < columns; ++i)
    for (int k = 0; k < cells; ++k)
      mu[static_cast<std::size_t>(i) * cells + k] = column_mass * (1 + amplitude * xi[i]) / cells;
  return mu;
}

std::vector<double> columnStart(const GranularHydro2D& op, double theta, bool spread) {
  const int N = op.cells();
  std::vector<double> U(op.size(), 0.0);
  for (int i = 0; i < op.columns(); ++i) {
    const double mu = op.initialCellMass()[static_cast<std::size_t>(i) * N];
    for (int k = 1; k < N; ++k)
      if (op.initialCellMass()[static_cast<std::size_t>(i) * N + k] != mu)
        throw std::invalid_argument("a column's cells start with equal masses");
    const GranularHydro1D column(op.geometry(), op.model(), mu * N, op.regularisation());
    const std::vector<double> V = spread ? spreadLayer(column, theta) : settledLayer(column, theta);
    for (int j = 0; j <= N; ++j) {
      U[op.heightIndex(i, j)] = V[column.heightIndex(j)];
      U[op.velocityIndex(i, j)] = V[column.velocityIndex(j)];
      if (j == N) break;
      U[op.temperatureIndex(i, j)] = V[column.temperatureIndex(j)];
      if (op.rough()) U[op.rotationIndex(i, j)] = V[column.rotationIndex(j)];
    }
  }
  return U;
}

}  // namespace granwave::hydro
