/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "timeDirectories.H"
#include "OSspecific.H"
#include "runSignals.H"
#include "OStringStream.H"
#include "fileOperation.H"
#include "wallClock.H"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <pthread.h>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace Foam
{

const word stagingDirName(".savageHutterFoam-writing");

namespace
{

//- Time's purgeWrite, which would remove directories by their staged path
struct timeAccess : public Time
{
    static label& purgeWrite(Time& t)
    {
        return t.*(&timeAccess::purgeWrite_);
    }
};

//- What failed in writing a time directory ("Cannot <what> <path>: why"),
//  thrown on whichever thread writes and reported on the solver's
struct writeFailure
{
    std::string message;
};

std::string whatFailed
(
    const char* what,
    const fileName& path,
    const std::string& why
)
{
    return std::string("Cannot ") + what + " " + path + ": " + why;
}

[[noreturn]] void failing
(
    const char* what,
    const fileName& path,
    const std::string& why = std::strerror(errno)
)
{
    throw writeFailure{whatFailed(what, path, why)};
}

[[noreturn]] void report(const std::string& message)
{
    FatalErrorInFunction
        << message.c_str() << nl
        << "The time directories written before are intact; the next start"
        << " removes " << stagingDirName << "." << nl
        << exit(FatalError);
    std::abort();
}

[[noreturn]] void failed
(
    const char* what,
    const fileName& path,
    const std::string& why = std::strerror(errno)
)
{
    report(whatFailed(what, path, why));
}

//- Flush a file or directory to disk; its size
off_t syncPath(const fileName& path)
{
    const int fd = ::open(path.c_str(), O_RDONLY);
    struct stat st;
    if (fd < 0 || ::fsync(fd) != 0 || ::fstat(fd, &st) != 0)
    {
        const std::string why = std::strerror(errno);
        if (fd >= 0)
        {
            ::close(fd);
        }
        failing("flush to disk", path, why);
    }
    ::close(fd);
    return S_ISREG(st.st_mode) ? st.st_size : 0;
}

//- Start the writeback of every file of a tree, not waiting for it:
//  fsync, one file after the other, then waits for data already on its
//  way to the disk (best effort: errors are fsync's to report)
void startWriteback(const fileName& dir)
{
#ifdef SYNC_FILE_RANGE_WRITE
    for (const fileName& f : readDir(dir, fileName::FILE, false, false))
    {
        const int fd = ::open((dir/f).c_str(), O_RDONLY);
        if (fd >= 0)
        {
            ::sync_file_range(fd, 0, 0, SYNC_FILE_RANGE_WRITE);
            ::close(fd);
        }
    }
    for (const fileName& d : readDir(dir, fileName::DIRECTORY, false, false))
    {
        startWriteback(dir/d);
    }
#endif
}

//- Flush a directory tree to disk; the bytes of its files
double syncTree(const fileName& dir)
{
    double bytes = 0;
    for (const fileName& f : readDir(dir, fileName::FILE, false, false))
    {
        bytes += syncPath(dir/f);
    }
    for (const fileName& d : readDir(dir, fileName::DIRECTORY, false, false))
    {
        bytes += syncTree(dir/d);
    }
    syncPath(dir);
    return bytes;
}

void renameOrFail(const fileName& from, const fileName& to)
{
    if (::rename(from.c_str(), to.c_str()) != 0)
    {
        failing("rename into place", from);
    }
}

//- Swap two directories in one step (Linux renameat2 RENAME_EXCHANGE):
//  false where the file system or kernel does not offer it
bool exchange(const fileName& a, const fileName& b)
{
    // The tests take the fallback through SH_NO_RENAME_EXCHANGE=1
    static const bool off = std::getenv("SH_NO_RENAME_EXCHANGE") != nullptr;
    if (off)
    {
        return false;
    }
#ifdef RENAME_EXCHANGE
    if (::renameat2(AT_FDCWD, a.c_str(), AT_FDCWD, b.c_str(), RENAME_EXCHANGE) == 0)
    {
        return true;
    }
    if (errno != EINVAL && errno != ENOSYS && errno != ENOTSUP)
    {
        failing("swap into place", a);
    }
#endif
    return false;
}

//- The suffix under which the fallback moves a directory being replaced
const char* const replacedSuffix = ".replaced";

} // namespace


void restoreReplaced(const fileName& caseDir)
{
    const fileName staging = caseDir/stagingDirName;
    if (!isDir(staging, false))
    {
        return;
    }
    // A time directory being replaced when the run was killed (only where
    // the directories cannot be swapped in one step, see write()): it was
    // complete, and the new one never took its place
    const std::string::size_type len = std::strlen(replacedSuffix);
    for
    (
        const fileName& d
      : readDir(staging, fileName::DIRECTORY, false, false)
    )
    {
        const std::string n(d);
        if
        (
            n.size() > len
         && n.compare(n.size() - len, len, replacedSuffix) == 0
        )
        {
            const fileName target = caseDir/n.substr(0, n.size() - len);
            if (!isDir(target, false))
            {
                WarningInFunction
                    << "Restoring " << target << " from " << staging/d
                    << ": a run was stopped while replacing it" << nl
                    << endl;
                try
                {
                    renameOrFail(staging/d, target);
                }
                catch (const writeFailure& f)
                {
                    report(f.message);
                }
            }
        }
    }
}


void removeIncompleteWrites(const Time& runTime)
{
    const fileName staging = runTime.path()/stagingDirName;
    if (!isDir(staging, false))
    {
        return;
    }
    WarningInFunction
        << "Removing " << staging << " with "
        << flatOutput(readDir(staging, fileName::DIRECTORY, false, false))
        << ": incomplete time directories of a run stopped while writing"
        << " them (killed, out of memory, node lost); the complete time"
        << " directories are kept" << nl << endl;
    if (!rmDir(staging))
    {
        failed("remove", staging);
    }
}


void checkWritable(const Time& runTime)
{
    const fileName staging = runTime.path()/stagingDirName;
    if (::mkdir(staging.c_str(), 0777) != 0 && errno != EEXIST)
    {
        const std::string why = std::strerror(errno);
        FatalErrorInFunction
            << "Cannot write into the case directory " << runTime.path()
            << ": creating " << staging << " failed: " << why.c_str() << nl
            << "Nothing was written; make the case directory writable"
            << " (or copy the case to a writable place) and start again."
            << nl << exit(FatalError);
    }
    rmDir(staging);
}


void removeUnsharedTimes(const fileName& processorDir)
{
    if (!Pstream::parRun())
    {
        return;
    }
    const instantList times = Time::findTimes(processorDir, "constant");
    const scalar mine = times.size() ? times.last().value() : -VGREAT;
    const scalar common = returnReduce(mine, minOp<scalar>());
    const scalar latest = returnReduce(mine, maxOp<scalar>());
    if (common == latest)
    {
        return;
    }
    // Only when every processor holds that earliest latest time: else the
    // directories are not a stopped run's (a processor without times, or
    // times that do not nest), and nothing is removed (Time then names
    // the processors whose start times differ)
    bool holds = false;
    forAll(times, i)
    {
        holds = holds || times[i].value() == common;
    }
    if (!returnReduce(holds, andOp<bool>()))
    {
        Info<< "The processors' latest times range over [" << common << ", "
            << latest << "], and not every processor holds " << common
            << ": nothing removed" << nl << endl;
        return;
    }
    forAll(times, i)
    {
        if (times[i].value() > common)
        {
            const fileName dir = processorDir/times[i].name();
            Pout<< "Time " << times[i].name() << " of " << dir << " is"
                << " missing on other processors (a decomposed run stopped"
                << " while writing): removed" << endl;
            if (!rmDir(dir))
            {
                FatalErrorInFunction
                    << "Cannot remove " << dir << ", a time the other"
                    << " processors lack; remove it by hand" << nl
                    << exit(FatalError);
            }
        }
    }
    Info<< "The processors' latest times range over [" << common << ", "
        << latest << "]: all start from " << common << nl << endl;
}


namespace
{

[[noreturn]] void hintAndExit(const Time& runTime, const string& file)
{
    const fileName startDir = runTime.timePath();
    const bool inStart =
        file.size() > startDir.size()
     && file.compare(0, startDir.size(), startDir) == 0
     && file[startDir.size()] == '/';
    const instantList times =
        Time::findTimes(runTime.path(), runTime.constant());
    label before = -1;
    forAll(times, i)
    {
        if (times[i].value() < runTime.value() && times[i].name() != "constant")
        {
            before = i;
        }
    }
    if (inStart && before >= 0)
    {
        Perr<< nl << "The start time directory " << runTime.timeName()
            << " cannot be read (above). A run killed while writing it"
            << " (before time directories were written whole), or an edit,"
            << " may have cut it short. Nothing is written. To restart from"
            << " " << times[before].name() << ", the time before it:" << nl
            << "    rm -r " << startDir << nl;
    }
    else if (inStart)
    {
        Perr<< nl << "The start time directory " << runTime.timeName()
            << " cannot be read (above). Nothing is written." << nl;
    }
    if (inStart)
    {
        // Files the run can do without (each loses something)
        const word name = fileName(file).name();
        const char* without =
            name == "hU" ? "the restart then takes h U as the momentum,"
            " not bit for bit"
          : name == "hMax" || name == "UMax"
          ? "the peak maps then start again from the start time's state"
          : name == "pMax"
          ? "pMax then continues from rho UMax^2, to round-off"
          : name == "tArrival"
          ? "cells already reached then take the start time as arrival"
            " time"
          : name == "time" ? "the start time is then read from the"
            " directory's name, to its timePrecision digits"
          : nullptr;
        if (without)
        {
            Perr<< "Or remove only this file (" << without << "):" << nl
                << "    rm " << file << nl;
        }
    }
    Perr<< nl << "FOAM exiting" << nl << endl;
    if (Pstream::parRun())
    {
        // Every processor ends, not only this one (as FatalError does)
        UPstream::abort();
    }
    std::exit(1);
}

} // namespace


void reportUnreadable(const Time& runTime, const IOerror& err)
{
    Perr<< nl << err << nl;
    hintAndExit(runTime, err.ioFileName());
}


void reportUnreadable(const Time& runTime, const error& err)
{
    Perr<< nl << err << nl;
    hintAndExit(runTime, string::null);
}


void reportUnreadableFile
(
    const Time& runTime,
    const fileName& file,
    const string& why
)
{
    const bool throws = FatalIOError.throwExceptions();
    try
    {
        FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, file)
            << file << " " << why.c_str() << nl << exit(FatalIOError);
    }
    catch (const IOerror& e)
    {
        FatalIOError.throwExceptions(throws);
        reportUnreadable(runTime, e);
    }
    std::abort();
}


namespace
{

//- Why writes may not overlap the steps (empty: they may)
std::string overlapRefused()
{
    // The tests compare with writes on the solver's thread
    const char* env = std::getenv("SH_OVERLAP_WRITES");
    if (env && std::string(env) == "0")
    {
        return "SH_OVERLAP_WRITES=0";
    }
    // The uncollated handler writes each processor's files itself with
    // no communication (fileOperation::writeObject, OFstream); the
    // collated and masterUncollated handlers send the data to the master,
    // which only the solver's thread may do (MPI)
    if (fileHandler().type() != "uncollated")
    {
        return "fileHandler " + fileHandler().type() + " communicates"
            " between processors; only uncollated writes overlap the steps";
    }
    return std::string();
}

//- Seconds from a test hook's environment variable (0: unset)
double testSeconds(const char* var)
{
    const char* env = std::getenv(var);
    return env ? std::atof(env) : 0;
}

//- Sleep that long (nothing for 0)
void sleepFor(const double seconds)
{
    if (seconds > 0)
    {
        std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
    }
}

//- An OpenFOAM error as OpenFOAM prints it (IOerror with its file and
//  line: its own operator<<, which error's does not call)
template<class Error>
std::string foamMessage(const Error& e)
{
    OStringStream os;
    os << e;
    return os.str();
}

} // namespace


atomicWriter::atomicWriter(Time& runTime)
:
    runTime_(runTime),
    purgeWrite_(timeAccess::purgeWrite(runTime)),
    notOverlapped_(overlapRefused()),
    overlap_(notOverlapped_.empty())
{
    timeAccess::purgeWrite(runTime) = 0;
}


atomicWriter::atomicWriter
(
    Time& runTime,
    const fileName& within,
    const label purgeWrite
)
:
    runTime_(runTime),
    purgeWrite_(purgeWrite),
    within_(within),
    notOverlapped_("an ensemble member's or statistics' writer"),
    overlap_(false)
{}


atomicWriter::~atomicWriter()
{
    if (thread_.joinable())
    {
        thread_.join();
    }
}


void atomicWriter::writeStaged(const fileName& staged)
{
    // Time writes under path() = rootPath()/caseName()
    fileName& caseName = runTime_.caseName();
    const fileName realCase = caseName;
    caseName =
        within_.empty() ? realCase/stagingDirName
      : realCase/within_/stagingDirName;
    // A stream that fails (disk full) is a FatalIOError inside Time
    // (thrown: write() and wait() set throwExceptions), reported with
    // what it means for the case
    const std::string why =
        "a file of it could not be written (disk full, quota, file size"
        " limit or permissions?)";
    bool ok = false;
    try
    {
        ok = runTime_.writeNow();
    }
    catch (const IOerror& e)
    {
        foamError_ = foamMessage(e);
    }
    catch (const error& e)
    {
        foamError_ = foamMessage(e);
    }
    caseName = realCase;
    if (!ok || !isDir(staged, false))
    {
        failing("write", staged, why);
    }
    const wallClock::time_point synced = wallClock::now();
    startWriteback(staged);
    bytes_ += syncTree(staged);
    syncSeconds_ += secondsSince(synced);
}

namespace
{

//- staging/name renamed to caseDir/name.  A directory of that name from
//  an earlier run (a restart from an earlier time) is replaced.  rename()
//  does not replace a non-empty directory: the two are swapped in one
//  step, after which the old one lies in the staging directory, so that
//  <time> is at every moment the old directory or the new one, both
//  complete.  Where the file system cannot swap, the old one is moved
//  aside first, a second SIGTERM/SIGINT held back over the two renames; a
//  run killed between them leaves it as <time>.replaced, which the next
//  start moves back (restoreReplaced).
void moveIntoPlace
(
    const fileName& caseDir,
    const fileName& staging,
    const word& name
)
{
    const fileName staged = staging/name;
    const fileName target = caseDir/name;
    if (isDir(target, false))
    {
        if (exchange(staged, target))
        {
            syncPath(caseDir);
            rmDir(staged);
        }
        else
        {
            const fileName aside = staging/(name + replacedSuffix);
            {
                runSignals::holdEnd held;
                renameOrFail(target, aside);
                renameOrFail(staged, target);
                syncPath(caseDir);
            }
            rmDir(aside);
        }
    }
    else
    {
        renameOrFail(staged, target);
        syncPath(caseDir);
    }
}

} // namespace


void atomicWriter::writeTime(const word& name, const bool restart)
{
    const fileName caseDir =
        within_.empty() ? runTime_.path() : runTime_.path()/within_;
    const fileName staging = caseDir/stagingDirName;
    const fileName staged = staging/name;
    if (isDir(staged, false))
    {
        rmDir(staged);
    }

    writeStaged(staged);
    moveIntoPlace(caseDir, staging, name);
    ::rmdir(staging.c_str());

    const bool again = !written_.empty() && written_.top() == name;
    if (!again)
    {
        written_.push(name);
    }
    if (restart)
    {
        // The one kept beyond purgeWrite is no longer the latest
        if (!keptRestart_.empty() && keptRestart_ != name)
        {
            rmDir(caseDir/keptRestart_);
            keptRestart_.clear();
        }
        lastRestart_ = name;
    }
    while (purgeWrite_ > 0 && written_.size() > purgeWrite_)
    {
        const word old = written_.pop();
        if (old == lastRestart_)
        {
            keptRestart_ = old;
        }
        else
        {
            rmDir(caseDir/old);
        }
    }
}


void atomicWriter::catching
(
    const word& name,
    const std::function<void()>& step
)
{
    try
    {
        step();
    }
    catch (const writeFailure& f)
    {
        failure_ = f.message;
    }
    catch (const IOerror& e)
    {
        // From OpenFOAM outside Time's writer (mkDir, readDir)
        foamError_ = foamMessage(e);
        failure_ = whatFailed("write", name, "see above");
    }
    catch (const error& e)
    {
        foamError_ = foamMessage(e);
        failure_ = whatFailed("write", name, "see above");
    }
    catch (const std::exception& e)
    {
        failure_ = whatFailed("write", name, e.what());
    }
}


void atomicWriter::releaseFilled()
{
    {
        std::lock_guard<std::mutex> lock(mutex_);
        filled_ = true;
    }
    filledChanged_.notify_all();
}


void atomicWriter::writeCatching
(
    const word& name,
    const bool restart,
    const std::function<void()>& fill
)
{
    const wallClock::time_point start = wallClock::now();
    if (fill)
    {
        catching(name, fill);
        fillSeconds_ += secondsSince(start);
    }
    releaseFilled();
    // The tests hold a write in flight this long (seconds), to signal or
    // step during it
    static const double delay = testSeconds("SH_TEST_WRITE_DELAY");
    sleepFor(delay);
    if (failure_.empty())
    {
        catching(name, [&]() { writeTime(name, restart); });
    }
    writeSeconds_ += secondsSince(start);
    ++nWrites_;
}


void atomicWriter::reportFailure() const
{
    if (!foamError_.empty())
    {
        Perr<< nl << foamError_.c_str() << nl;
    }
    report(failure_);
}


void atomicWriter::write
(
    const bool restart,
    const std::function<void()>& fill
)
{
    wait();
    const word name = runTime_.timeName();
    // The tests make the fill this long (seconds), to see on which
    // thread it runs
    static const double fillDelay = testSeconds("SH_TEST_FILL_DELAY");
    std::function<void()> fillInWrite = fill;
    if (fill && fillDelay > 0)
    {
        fillInWrite = [fill]() { sleepFor(fillDelay); fill(); };
    }
    // Decomposed: the fields' boundary conditions exchange across
    // processor patches (MPI), which only the caller's thread may do
    if (fill && overlap_ && !fillsOnWriter())
    {
        const wallClock::time_point start = wallClock::now();
        fillInWrite();
        fillSeconds_ += secondsSince(start);
        fillInWrite = nullptr;
    }
    // Errors inside Time's writer and OpenFOAM's file functions throw, to
    // be caught and reported here or by wait()
    ioThrew_ = FatalIOError.throwExceptions();
    threw_ = FatalError.throwExceptions();
    if (!overlap_)
    {
        writeCatching(name, restart, fillInWrite);
        FatalIOError.throwExceptions(ioThrew_);
        FatalError.throwExceptions(threw_);
        if (!failure_.empty())
        {
            reportFailure();
        }
        return;
    }
    filled_ = false;
    // SIGTERM, SIGINT, SIGUSR1 stay with the solver's thread: the writer
    // thread starts with them blocked (a thread inherits its creator's
    // mask)
    sigset_t mask, old;
    sigemptyset(&mask);
    sigaddset(&mask, SIGTERM);
    sigaddset(&mask, SIGINT);
    sigaddset(&mask, SIGUSR1);
    pthread_sigmask(SIG_BLOCK, &mask, &old);
    thread_ = std::thread
    (
        [this, name, restart, fillInWrite]()
        {
            writeCatching(name, restart, fillInWrite);
        }
    );
    pthread_sigmask(SIG_SETMASK, &old, nullptr);
}


void atomicWriter::waitFilled()
{
    if (!thread_.joinable())
    {
        return;
    }
    const wallClock::time_point start = wallClock::now();
    std::unique_lock<std::mutex> lock(mutex_);
    filledChanged_.wait(lock, [this]() { return filled_; });
    waitSeconds_ += secondsSince(start);
}


void atomicWriter::wait()
{
    if (!thread_.joinable())
    {
        return;
    }
    const wallClock::time_point start = wallClock::now();
    thread_.join();
    waitSeconds_ += secondsSince(start);
    FatalIOError.throwExceptions(ioThrew_);
    FatalError.throwExceptions(threw_);
    if (!failure_.empty())
    {
        reportFailure();
    }
}

} // End namespace Foam
