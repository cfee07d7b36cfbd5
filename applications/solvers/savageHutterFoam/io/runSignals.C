/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "runSignals.H"

#include <sys/types.h>
#include <unistd.h>
#include <cstring>
#include <initializer_list>

namespace Foam
{
namespace runSignals
{

volatile std::sig_atomic_t pending = 0;
volatile std::sig_atomic_t stop = 0;
volatile std::sig_atomic_t last = 0;

namespace
{

//- Inside a holdEnd, and the ending signal held back there (0: none)
volatile std::sig_atomic_t holding = 0;
volatile std::sig_atomic_t held = 0;

void endBy(const int sig)
{
    std::signal(sig, SIG_DFL);
    // To the process, not the thread (raise): a holdEnd on the writer
    // thread, which blocks these signals, ends there
    ::kill(::getpid(), sig);
}

extern "C" void onSignal(int sig)
{
    if (sig != SIGUSR1)
    {
        if (stop)
        {
            // The second one: the user does not want to wait
            if (holding)
            {
                held = sig;
            }
            else
            {
                endBy(sig);
            }
            return;
        }
        stop = 1;
    }
    last = sig;
    pending = 1;
}

} // namespace


holdEnd::holdEnd()
{
    holding = 1;
}


holdEnd::~holdEnd()
{
    holding = 0;
    if (held)
    {
        endBy(held);
    }
}


void install()
{
    struct sigaction sa;
    std::memset(&sa, 0, sizeof(sa));
    sa.sa_handler = onSignal;
    sigemptyset(&sa.sa_mask);
    // Interrupted reads and writes of the case go on
    sa.sa_flags = SA_RESTART;
    for (const int sig : {SIGTERM, SIGINT, SIGUSR1})
    {
        sigaction(sig, &sa, nullptr);
    }
}


const char* name(const int sig)
{
    switch (sig)
    {
        case SIGTERM: return "SIGTERM";
        case SIGINT: return "SIGINT";
        case SIGUSR1: return "SIGUSR1";
        default: return "a signal";
    }
}

} // End namespace runSignals
} // End namespace Foam
