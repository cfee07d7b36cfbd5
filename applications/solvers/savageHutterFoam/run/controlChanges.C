/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver

Description
    A controlDict changed during a run (runTimeModifiable yes): endTime,
    writeControl, writeInterval and stopAt act from the next step; an
    invalid one is reported and the run goes on as before.
\*---------------------------------------------------------------------------*/

#include "avalancheRun.H"
#include "anyProcessor.H"
#include "controlSettings.H"
#include "OStringStream.H"

namespace Foam
{

template<class Real>
bool avalancheRun<Real>::readChangedControl(controlSettings& c) const
{
    const bool ioThrows = FatalIOError.throwExceptions();
    const bool throws = FatalError.throwExceptions();
    bool valid = true;
    try
    {
        c = controlSettings::readFile(controlDictPath_, true);
    }
    catch (const error& e)
    {
        valid = false;
        Warning
            << nl << "controlDict changed at t = " << solver_->time()
            << " but is invalid; the run goes on as before:" << nl
            << e.message().c_str() << nl << "file: "
            << controlDictPath_ << nl << endl;
    }
    FatalIOError.throwExceptions(ioThrows);
    FatalError.throwExceptions(throws);
    return valid;
}


template<class Real>
bool avalancheRun<Real>::controlDiffers(const controlSettings& c) const
{
    // Every setting the run acts on, as numbers
    const wordList controls
    ({
        "timeStep", "runTime", "adjustableRunTime", "clockTime",
        "cpuTime", "endTime", "writeNow", "noWriteNow", "nextWrite"
    });
    const auto differs = [](const scalar x)
    {
        return returnReduce(x, minOp<scalar>())
            != returnReduce(x, maxOp<scalar>());
    };
    return
        differs(c.endTime) || differs(c.writeInterval)
     || differs(controls.find(c.writeControl))
     || differs(controls.find(c.stopAt))
     || differs(c.runTimeModifiable);
}


template<class Real>
bool avalancheRun<Real>::controlStepsValid(const controlSettings& c) const
{
    // The new endTime and writes from here, at the steps of the start
    const double t = solver_->time();
    const bool onGrid =
        c.writeControl == "adjustableRunTime"
     || c.writeControl == "runTime";
    const std::string why = stepsProblem
    (
        t, c.endTime, c.writeControl, c.writeInterval,
        onGrid ? t + c.writeInterval : c.endTime
    );
    if (!why.empty())
    {
        Warning
            << nl << "controlDict changed at t = " << t << " but is"
            << " invalid; the run goes on as before:" << nl
            << why.c_str() << nl << "file: " << controlDictPath_ << nl
            << endl;
        return false;
    }
    return true;
}


template<class Real>
void avalancheRun<Real>::applyControl(const controlSettings& c)
{
    controlSettings& now = ac_.input.control;
    Info<< nl << "controlDict changed at t = " << solver_->time() << ":";
    if (c.endTime != endTime_)
    {
        Info<< " endTime " << endTime_ << " -> " << c.endTime << ";";
        endTime_ = c.endTime;
        runTime_.setEndTime(endTime_);
    }
    if
    (
        c.writeControl != ac_.input.writeControl
     || c.writeInterval != ac_.input.writeInterval
    )
    {
        Info<< " writeControl " << c.writeControl << ", writeInterval "
            << ac_.input.writeInterval << " -> " << c.writeInterval << ";";
        ac_.input.writeControl = c.writeControl;
        ac_.input.writeInterval = c.writeInterval;
        nextWrite_ = -GREAT;
    }
    if (c.stopAt != now.stopAt)
    {
        Info<< " stopAt " << c.stopAt << ";";
    }
    if
    (
        c.deltaT != now.deltaT || c.maxCo != now.maxCo
     || c.maxDeltaT != now.maxDeltaT
     || c.adjustTimeStep != now.adjustTimeStep
     || c.purgeWrite != now.purgeWrite
     || c.writeFields != now.writeFields
     || c.restartInterval != now.restartInterval
    )
    {
        Info<< " (deltaT, maxCo, maxDeltaT, adjustTimeStep, purgeWrite,"
            << " writeFields and restartInterval are read at the next"
            << " start)";
    }
    Info<< nl << endl;
    now.endTime = c.endTime;
    now.writeControl = c.writeControl;
    now.writeInterval = c.writeInterval;
    now.stopAt = c.stopAt;
    now.runTimeModifiable = c.runTimeModifiable;
}


template<class Real>
bool avalancheRun<Real>::stopOnControl(const controlSettings& c)
{
    stopAtNextWrite_ = c.stopAt == "nextWrite";
    if (c.stopAt == "noWriteNow")
    {
        stoppedBy_ = "stopAt noWriteNow";
        return true;
    }
    if (c.stopAt == "writeNow" || !(solver_->time() < endTime_))
    {
        stoppedBy_ = c.stopAt == "writeNow" ? "stopAt writeNow" : "endTime";
        // The last write: with the restart fields (again at a time
        // written without them)
        write(true);
        return true;
    }
    return false;
}


template<class Real>
bool avalancheRun<Real>::readControlIfModified()
{
    lastCheck_ = wallClock::now();
    const double stamp = highResLastModified(controlDictPath_);
    if
    (
        !anyProcessor
        (
            ac_.input.control.runTimeModifiable && stamp != controlStamp_
        )
    )
    {
        return false;
    }
    controlStamp_ = stamp;
    // Writing format and precision may change: not under a write in
    // flight
    finishWrite();
    controlSettings c;
    bool valid = readChangedControl(c);
    // Decomposed: every processor read the same file (one edited between
    // their reads is read again at the next look)
    if (Pstream::parRun())
    {
        valid = !anyProcessor(!valid);
        if (valid && controlDiffers(c))
        {
            controlStamp_ = -1;
            return false;
        }
    }
    if (valid)
    {
        valid = controlStepsValid(c);
    }
    if (!valid)
    {
        return false;
    }

    applyControl(c);
    return stopOnControl(c);
}

// * * * * * * * * * * * * * * Instantiations  * * * * * * * * * * * * * * //

template bool avalancheRun<float>::readControlIfModified();
template bool avalancheRun<double>::readControlIfModified();

} // End namespace Foam
