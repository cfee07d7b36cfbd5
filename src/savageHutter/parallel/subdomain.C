#include "halo.H"

#include <stdexcept>
#include <string>

namespace sh
{

namespace
{

//- Start of part a of n cells cut into p parts, the first n mod p one
//  cell larger
int partStart(int n, int p, int a)
{
    const int base = n/p;
    const int extra = n%p;
    return a*base + (a < extra ? a : extra);
}

} // namespace


Subdomain splitGrid(int nx, int ny, int px, int py, int rank)
{
    if (px < 1 || py < 1 || rank < 0 || rank >= px*py)
    {
        throw std::invalid_argument
        (
            "splitGrid: rank " + std::to_string(rank) + " of a "
          + std::to_string(px) + " x " + std::to_string(py) + " split"
        );
    }
    if (nx/px < Grid<double>::ng || ny/py < Grid<double>::ng)
    {
        throw std::invalid_argument
        (
            "splitGrid: " + std::to_string(nx) + " x " + std::to_string(ny)
          + " cells cut into " + std::to_string(px) + " x "
          + std::to_string(py) + " parts leaves a part narrower than the "
          + std::to_string(Grid<double>::ng) + " ghost layers"
        );
    }
    const int a = rank%px;
    const int b = rank/px;
    Subdomain s;
    s.nxWhole = nx;
    s.nyWhole = ny;
    s.i0 = partStart(nx, px, a);
    s.j0 = partStart(ny, py, b);
    s.nx = partStart(nx, px, a + 1) - s.i0;
    s.ny = partStart(ny, py, b + 1) - s.j0;
    s.neighbour[xMin] = a > 0 ? rank - 1 : -1;
    s.neighbour[xMax] = a < px - 1 ? rank + 1 : -1;
    s.neighbour[yMin] = b > 0 ? rank - px : -1;
    s.neighbour[yMax] = b < py - 1 ? rank + px : -1;
    return s;
}


} // namespace sh
