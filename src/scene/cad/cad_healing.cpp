// cad_healing.cpp - STEP shape healing switched and timed through an operator of idview's own
// (cad_healing.h).
#include "scene/cad/cad_healing.h"

#include <chrono>
#include <mutex>

#include <Interface_Static.hxx>
#include <Resource_Manager.hxx>
#include <ShapeProcess.hxx>
#include <ShapeProcess_Context.hxx>
#include <ShapeProcess_UOperator.hxx>

namespace scene::cad {
namespace {

constexpr const char* kTimed = "idviewFixShape";
constexpr const char* kNone = "idviewNoHealing";

std::mutex timeLock;
double healedMs = 0.0;

// Open CASCADE's FixShape, as the resource file configures it: the scope is the operator's
// name, so FixShape's parameters ("FromSTEP.FixShape.*") are read under its own.
Standard_Boolean timedFixShape(const Handle(ShapeProcess_Context) & context,
                               const Message_ProgressRange& range) {
    Handle(ShapeProcess_Operator) fix;
    if (!ShapeProcess::FindOperator("FixShape", fix)) return Standard_False;
    const auto start = std::chrono::steady_clock::now();
    context->UnSetScope();
    context->SetScope("FixShape");
    const Standard_Boolean done = fix->Perform(context, range);
    context->UnSetScope();
    context->SetScope(kTimed); // as ShapeProcess left it, for its own UnSetScope
    const std::lock_guard lock(timeLock);
    healedMs +=
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return done;
}

Standard_Boolean noHealing(const Handle(ShapeProcess_Context) &, const Message_ProgressRange&) {
    return Standard_True;
}

} // namespace

void setStepHealing(bool on) {
    static std::once_flag registered;
    std::call_once(registered, [] {
        ShapeProcess::RegisterOperator(kTimed, new ShapeProcess_UOperator(timedFixShape));
        ShapeProcess::RegisterOperator(kNone, new ShapeProcess_UOperator(noHealing));
    });
    // The resource the STEP reader's healing reads, kept by Open CASCADE once loaded (it is
    // loaded again only when its file changes): the sequence's operators are set on it.
    const char* name = Interface_Static::IsPresent("read.step.resource.name")
                           ? Interface_Static::CVal("read.step.resource.name")
                           : "STEP";
    const char* sequence = Interface_Static::IsPresent("read.step.sequence")
                               ? Interface_Static::CVal("read.step.sequence")
                               : "FromSTEP";
    Handle(ShapeProcess_Context) context = new ShapeProcess_Context;
    const Handle(Resource_Manager) resource = context->LoadResourceManager(name);
    const std::string key = std::string(sequence) + ".exec.op";
    resource->SetResource(key.c_str(), on ? kTimed : kNone);
}

double takeHealingMs() {
    const std::lock_guard lock(timeLock);
    const double ms = healedMs;
    healedMs = 0.0;
    return ms;
}

} // namespace scene::cad
