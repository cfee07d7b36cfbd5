#include "mpiHalo.H"

// Open MPI's extensions: MPIX_Query_cuda_support()
#if defined(OPEN_MPI) && OPEN_MPI
#   include <mpi-ext.h>
#endif

#include <climits>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

namespace sh
{

namespace
{

template<class Real> MPI_Datatype mpiType();
template<> MPI_Datatype mpiType<double>() { return MPI_DOUBLE; }
template<> MPI_Datatype mpiType<float>() { return MPI_FLOAT; }

const char* sideName(int side)
{
    static const char* const names[4] = {"xMin", "xMax", "yMin", "yMax"};
    return side >= 0 && side < 4 ? names[side] : "?";
}

//- The side across from side (xMin <-> xMax, yMin <-> yMax)
int opposite(int side)
{
    return side ^ 1;
}

std::string mpiErrorString(int code)
{
    char text[MPI_MAX_ERROR_STRING];
    int length = 0;
    if (MPI_Error_string(code, text, &length) != MPI_SUCCESS || length <= 0)
    {
        return "MPI error code " + std::to_string(code);
    }
    return std::string(text, std::size_t(length));
}

//- The fields of a Subdomain sent by validate(), in this order
constexpr int nSubFields = 10;

void pack(const Subdomain& s, int* f)
{
    f[0] = s.nxWhole;
    f[1] = s.nyWhole;
    f[2] = s.i0;
    f[3] = s.j0;
    f[4] = s.nx;
    f[5] = s.ny;
    for (int side = 0; side < 4; ++side)
    {
        f[6 + side] = s.neighbour[side];
    }
}

Subdomain unpack(const int* f)
{
    Subdomain s;
    s.nxWhole = f[0];
    s.nyWhole = f[1];
    s.i0 = f[2];
    s.j0 = f[3];
    s.nx = f[4];
    s.ny = f[5];
    for (int side = 0; side < 4; ++side)
    {
        s.neighbour[side] = f[6 + side];
    }
    return s;
}

std::string describe(int rank, const Subdomain& s)
{
    return "rank " + std::to_string(rank) + " (" + std::to_string(s.nx)
      + " x " + std::to_string(s.ny) + " cells at ("
      + std::to_string(s.i0) + ", " + std::to_string(s.j0) + "))";
}

//- What is wrong with the given side of rank r's subdomain among all
//  ranks' (splitError), "" if nothing: its neighbour, or the lack of one,
//  and how the two meet
std::string sideError(const std::vector<Subdomain>& subs, int r, int side)
{
    const int size = int(subs.size());
    const int ng = Grid<double>::ng;
    const Subdomain& s = subs[r];
    const int m = s.neighbour[side];
    if (m >= size)
    {
        return describe(r, s) + "'s " + sideName(side)
          + " neighbour is rank " + std::to_string(m)
          + ", beyond the " + std::to_string(size)
          + " ranks of the communicator";
    }
    // A side without a neighbour is a side of the whole grid, and
    // a side of the whole grid has none (no periodic wrap)
    const bool onEdge =
        side == xMin ? s.i0 == 0
      : side == xMax ? s.i0 + s.nx == s.nxWhole
      : side == yMin ? s.j0 == 0
      : s.j0 + s.ny == s.nyWhole;
    if ((m < 0) != onEdge)
    {
        return describe(r, s) + "'s " + sideName(side) + " side "
          + (onEdge
            ? "is a side of the whole grid but names a neighbour"
            : "lies inside the whole grid but names no neighbour");
    }
    if (m < 0)
    {
        return "";
    }
    const bool xSide = side == xMin || side == xMax;
    const std::string here =
        describe(r, s) + "'s " + sideName(side) + " neighbour";
    if ((xSide ? s.nx : s.ny) < ng)
    {
        return describe(r, s) + " is narrower than the "
          + std::to_string(ng) + " ghost layers across its "
          + sideName(side) + " processor side";
    }
    const Subdomain& t = subs[m];
    if (t.neighbour[opposite(side)] != r)
    {
        return here + " " + describe(m, t) + " names rank "
          + std::to_string(t.neighbour[opposite(side)])
          + " across its " + sideName(opposite(side)) + " side";
    }
    // The shared side: its length and where it starts along it
    const int lengthHere = xSide ? s.ny : s.nx;
    const int lengthThere = xSide ? t.ny : t.nx;
    if (lengthHere != lengthThere)
    {
        return here + " " + describe(m, t) + " has "
          + std::to_string(lengthThere)
          + (xSide ? " rows" : " columns")
          + " along the shared side, rank " + std::to_string(r)
          + " has " + std::to_string(lengthHere);
    }
    if ((xSide ? s.j0 : s.i0) != (xSide ? t.j0 : t.i0))
    {
        return here + " " + describe(m, t)
          + " does not start the shared side at the same "
          + (xSide ? "row" : "column");
    }
    // Adjoining (across the whole grid's side where it wraps)
    const int lo = xSide ? s.i0 : s.j0;
    const int hi = lo + (xSide ? s.nx : s.ny);
    const int tLo = xSide ? t.i0 : t.j0;
    const int tHi = tLo + (xSide ? t.nx : t.ny);
    const bool adjoins = (side == xMin || side == yMin)
        ? tHi == lo
        : hi == tLo;
    if (!adjoins)
    {
        return here + " " + describe(m, t)
          + " does not adjoin it across that side";
    }
    return "";
}


//- What is wrong with the split of all ranks' subdomains, "" if nothing
std::string splitError(const std::vector<Subdomain>& subs)
{
    const int size = int(subs.size());
    const Subdomain& first = subs[0];
    if (first.nxWhole < 1 || first.nyWhole < 1)
    {
        return describe(0, first) + " names a whole grid of "
          + std::to_string(first.nxWhole) + " x "
          + std::to_string(first.nyWhole) + " cells";
    }
    for (int r = 0; r < size; ++r)
    {
        const Subdomain& s = subs[r];
        if (s.nxWhole != first.nxWhole || s.nyWhole != first.nyWhole)
        {
            return describe(r, s) + " names a whole grid of "
              + std::to_string(s.nxWhole) + " x " + std::to_string(s.nyWhole)
              + " cells, rank 0 one of " + std::to_string(first.nxWhole)
              + " x " + std::to_string(first.nyWhole);
        }
        if
        (
            s.nx < 1 || s.ny < 1 || s.i0 < 0 || s.j0 < 0
         || s.i0 + s.nx > s.nxWhole || s.j0 + s.ny > s.nyWhole
        )
        {
            return describe(r, s) + " does not lie in the whole grid of "
              + std::to_string(s.nxWhole) + " x "
              + std::to_string(s.nyWhole) + " cells";
        }
        for (int side = 0; side < 4; ++side)
        {
            const std::string error = sideError(subs, r, side);
            if (!error.empty())
            {
                return error;
            }
        }
    }
    // The parts cover the whole grid once: their cells add up to it (with
    // the sides checked above, rectangles that adjoin their neighbours
    // along whole sides and reach the grid's edges cannot overlap then)
    long long cells = 0;
    for (const Subdomain& s : subs)
    {
        cells += (long long)s.nx*s.ny;
    }
    if (cells != (long long)first.nxWhole*first.nyWhole)
    {
        return "the parts hold " + std::to_string(cells) + " cells, the"
            " whole grid " + std::to_string(first.nxWhole) + " x "
          + std::to_string(first.nyWhole);
    }
    return "";
}

//- Whether the MPI library reads and writes CUDA device memory itself:
//  Open MPI says so at run time (MPIX_Query_cuda_support, the library
//  loaded, not the headers built against); other MPIs are not asked.
//  SH_CUDA_AWARE_MPI=0 in the environment stages through the host anyway.
bool queryDeviceMemory()
{
    const char* env = std::getenv("SH_CUDA_AWARE_MPI");
    if (env && std::string(env) == "0")
    {
        return false;
    }
#if defined(OMPI_HAVE_MPI_EXT_CUDA) && OMPI_HAVE_MPI_EXT_CUDA
    return MPIX_Query_cuda_support() == 1;
#else
    return false;
#endif
}

} // namespace


template<class Real>
void MpiHalo<Real>::check(int code, const char* call)
{
    if (code != MPI_SUCCESS)
    {
        throw std::runtime_error
        (
            std::string("MpiHalo: ") + call + " failed: "
          + mpiErrorString(code)
        );
    }
}


template<class Real>
MpiHalo<Real>::MpiHalo(MPI_Comm comm, const Subdomain& s)
:
    sub_(s)
{
    int initialised = 0;
    check(MPI_Initialized(&initialised), "MPI_Initialized");
    if (!initialised)
    {
        throw std::runtime_error("MpiHalo: MPI is not initialised (MPI_Init)");
    }
    if (comm == MPI_COMM_NULL)
    {
        throw std::invalid_argument("MpiHalo: the communicator is MPI_COMM_NULL");
    }
    check(MPI_Comm_dup(comm, &comm_), "MPI_Comm_dup");
    try
    {
        check
        (
            MPI_Comm_set_errhandler(comm_, MPI_ERRORS_RETURN),
            "MPI_Comm_set_errhandler"
        );
        check(MPI_Comm_rank(comm_, &rank_), "MPI_Comm_rank");
        check(MPI_Comm_size(comm_, &size_), "MPI_Comm_size");
        validate();
        deviceMemory_ = queryDeviceMemory();
    }
    catch (...)
    {
        MPI_Comm_free(&comm_);      // its own failure is not the news
        comm_ = MPI_COMM_NULL;
        throw;
    }
}


template<class Real>
MpiHalo<Real>::~MpiHalo()
{
    if (comm_ == MPI_COMM_NULL)
    {
        return;
    }
    // A destructor must not throw: a failure to free is ignored, and after
    // MPI_Finalize the communicator is gone anyway
    int finalised = 1;
    if (MPI_Finalized(&finalised) == MPI_SUCCESS && !finalised)
    {
        MPI_Comm_free(&comm_);
    }
}


template<class Real>
void MpiHalo<Real>::validate() const
{
    int mine[nSubFields];
    pack(sub_, mine);
    std::vector<int> all(std::size_t(nSubFields)*size_);
    check
    (
        MPI_Allgather
        (
            mine, nSubFields, MPI_INT, all.data(), nSubFields, MPI_INT, comm_
        ),
        "MPI_Allgather (the subdomains)"
    );
    std::vector<Subdomain> subs(size_);
    for (int r = 0; r < size_; ++r)
    {
        subs[r] = unpack(all.data() + std::size_t(nSubFields)*r);
    }
    const std::string error = splitError(subs);
    if (!error.empty())
    {
        throw std::runtime_error
        (
            "MpiHalo: the subdomains of the " + std::to_string(size_)
          + " ranks do not fit together: " + error
        );
    }
}


template<class Real>
void MpiHalo<Real>::exchange(int dir, Real* const* arrays, int n, int width)
{
    const int ng = Grid<Real>::ng;
    if (dir != 0 && dir != 1)
    {
        throw std::invalid_argument
        (
            "MpiHalo::exchange: direction " + std::to_string(dir)
          + " (0: x-sides, 1: y-sides)"
        );
    }
    if (width < 1 || width > ng || n < 0 || (n > 0 && !arrays))
    {
        throw std::invalid_argument
        (
            "MpiHalo::exchange: width " + std::to_string(width) + " (1.."
          + std::to_string(ng) + ") of " + std::to_string(n) + " arrays"
        );
    }
    for (int a = 0; a < n; ++a)
    {
        if (!arrays[a])
        {
            throw std::invalid_argument
            (
                "MpiHalo::exchange: array " + std::to_string(a) + " is null"
            );
        }
    }
    const int first = 2*dir;            // xMin or yMin
    if
    (
        n == 0
     || (!sub_.processorSide(first) && !sub_.processorSide(first + 1))
    )
    {
        return;
    }

    const Strips strips = {dir, width, sub_.nx, sub_.ny};
    const std::size_t per = std::size_t(strips.perArray());
    Real* send[2];
    Real* recv[2];
    for (int b = 0; b < 2; ++b)
    {
        if (send_[b].size() < per*n)
        {
            send_[b].resize(per*n);
            recv_[b].resize(per*n);
        }
        send[b] = send_[b].data();
        recv[b] = recv_[b].data();
        if (!sub_.processorSide(first + b))
        {
            continue;
        }
        for (int a = 0; a < n; ++a)
        {
            for (std::size_t k = 0; k < per; ++k)
            {
                send[b][a*per + k] =
                    arrays[a][strips.cell(first + b, false, int(k))];
            }
        }
    }

    exchangePacked(strips, n, send, recv);

    for (int b = 0; b < 2; ++b)
    {
        if (!sub_.processorSide(first + b))
        {
            continue;
        }
        for (int a = 0; a < n; ++a)
        {
            for (std::size_t k = 0; k < per; ++k)
            {
                arrays[a][strips.cell(first + b, true, int(k))] =
                    recv[b][a*per + k];
            }
        }
    }
}


template<class Real>
int MpiHalo<Real>::messageCount(const Strips& strips, int n) const
{
    const int dir = strips.dir;
    if (dir != 0 && dir != 1)
    {
        throw std::invalid_argument
        (
            "MpiHalo::exchangePacked: direction " + std::to_string(dir)
          + " (0: x-sides, 1: y-sides)"
        );
    }
    if (strips.nx != sub_.nx || strips.ny != sub_.ny)
    {
        throw std::invalid_argument
        (
            "MpiHalo::exchangePacked: strips of a " + std::to_string(strips.nx)
          + " x " + std::to_string(strips.ny) + " grid on a subdomain of "
          + std::to_string(sub_.nx) + " x " + std::to_string(sub_.ny)
        );
    }
    // Values per message: n arrays of width columns of the interior rows,
    // or of width whole padded rows
    const long long total = (long long)(strips.perArray())*n;
    if (total > INT_MAX)
    {
        throw std::runtime_error
        (
            "MpiHalo::exchange: a message of " + std::to_string(total)
          + " values is beyond MPI's int count"
        );
    }
    return int(total);
}


template<class Real>
void MpiHalo<Real>::waitAll
(
    int nReq,
    MPI_Request* requests,
    MPI_Status* statuses,
    int nRecv,
    const int* sides
) const
{
    const int code = MPI_Waitall(nReq, requests, statuses);
    if (code != MPI_SUCCESS)
    {
        if (code == MPI_ERR_IN_STATUS)
        {
            for (int r = 0; r < nReq; ++r)
            {
                const int e = statuses[r].MPI_ERROR;
                if (e != MPI_SUCCESS && e != MPI_ERR_PENDING)
                {
                    throw std::runtime_error
                    (
                        std::string("MpiHalo: MPI_Waitall failed on the ")
                      + (r < nRecv ? "receive from" : "send to") + " rank "
                      + std::to_string(sub_.neighbour[sides[r]]) + " across "
                      + sideName(sides[r]) + ": " + mpiErrorString(e)
                    );
                }
            }
        }
        check(code, "MPI_Waitall");
    }
}


template<class Real>
void MpiHalo<Real>::checkCounts
(
    MPI_Status* statuses,
    int nRecv,
    const int* sides,
    int count,
    MPI_Datatype type
) const
{
    for (int r = 0; r < nRecv; ++r)
    {
        const int side = sides[r];
        int got = 0;
        check(MPI_Get_count(&statuses[r], type, &got), "MPI_Get_count");
        if (got != count)
        {
            throw std::runtime_error
            (
                "MpiHalo::exchange: " + std::to_string(got)
              + " values from rank " + std::to_string(sub_.neighbour[side])
              + " across " + sideName(side) + ", expected "
              + std::to_string(count)
            );
        }
    }
}


template<class Real>
void MpiHalo<Real>::exchangePacked
(
    const Strips& strips,
    int n,
    Real* const send[2],
    Real* const recv[2]
)
{
    const int first = 2*strips.dir;     // xMin or yMin
    const int count = messageCount(strips, n);
    if
    (
        count == 0
     || (!sub_.processorSide(first) && !sub_.processorSide(first + 1))
    )
    {
        return;
    }
    const MPI_Datatype type = mpiType<Real>();

    MPI_Request requests[4];
    int sides[4];
    int nRecv = 0;
    int nReq = 0;
    // Should posting fail half-way: no receive may be left to write into
    // the buffers later (codes ignored, the first failure is the news)
    const auto abandon = [&]()
    {
        for (int r = 0; r < nReq; ++r)
        {
            if (r < nRecv)
            {
                MPI_Cancel(&requests[r]);
                MPI_Wait(&requests[r], MPI_STATUS_IGNORE);
            }
            else
            {
                MPI_Request_free(&requests[r]);
            }
        }
    };
    try
    {
        for (int side = first; side < first + 2; ++side)
        {
            if (!sub_.processorSide(side))
            {
                continue;
            }
            check
            (
                MPI_Irecv
                (
                    recv[side - first], count, type, sub_.neighbour[side],
                    side, comm_, &requests[nRecv]
                ),
                "MPI_Irecv"
            );
            sides[nRecv++] = side;
            nReq = nRecv;
        }
        for (int side = first; side < first + 2; ++side)
        {
            if (!sub_.processorSide(side))
            {
                continue;
            }
            // Tagged with the side at which it arrives
            check
            (
                MPI_Isend
                (
                    send[side - first], count, type, sub_.neighbour[side],
                    opposite(side), comm_, &requests[nReq]
                ),
                "MPI_Isend"
            );
            sides[nReq++] = side;
        }
    }
    catch (...)
    {
        abandon();
        throw;
    }

    MPI_Status statuses[4];
    waitAll(nReq, requests, statuses, nRecv, sides);
    checkCounts(statuses, nRecv, sides, count, type);
}


template<class Real>
Real MpiHalo<Real>::maxAll(Real x)
{
    Real r = x;
    check
    (
        MPI_Allreduce(&x, &r, 1, mpiType<Real>(), MPI_MAX, comm_),
        "MPI_Allreduce (MPI_MAX)"
    );
    return r;
}


template<class Real>
Real MpiHalo<Real>::maxAll(Real x, bool& stop)
{
    // Both as doubles (exact for float), the flag as 0 or 1: the maximum
    // of the pair is the pair of maxima
    double v[2] = {double(x), stop ? 1.0 : 0.0};
    double r[2] = {v[0], v[1]};
    check
    (
        MPI_Allreduce(v, r, 2, MPI_DOUBLE, MPI_MAX, comm_),
        "MPI_Allreduce (MPI_MAX, the rate and the stop)"
    );
    stop = r[1] != 0.0;
    return Real(r[0]);
}


template<class Real>
double MpiHalo<Real>::sumAll(double x)
{
    double r = x;
    check
    (
        MPI_Allreduce(&x, &r, 1, MPI_DOUBLE, MPI_SUM, comm_),
        "MPI_Allreduce (MPI_SUM, double)"
    );
    return r;
}


template<class Real>
long long MpiHalo<Real>::sumAll(long long x)
{
    long long r = x;
    check
    (
        MPI_Allreduce(&x, &r, 1, MPI_LONG_LONG, MPI_SUM, comm_),
        "MPI_Allreduce (MPI_SUM, long long)"
    );
    return r;
}


template<class Real>
bool MpiHalo<Real>::anyAll(bool x)
{
    int v = x ? 1 : 0;
    int r = v;
    check
    (
        MPI_Allreduce(&v, &r, 1, MPI_INT, MPI_LOR, comm_),
        "MPI_Allreduce (MPI_LOR)"
    );
    return r != 0;
}


template class MpiHalo<double>;
template class MpiHalo<float>;

} // namespace sh
