#include <toposlam/planning/OmplPathPlanner.h>

#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/informedtrees/BITstar.h>
#include <ompl/geometric/planners/prm/PRMstar.h>
#include <ompl/geometric/planners/rrt/InformedRRTstar.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/util/Console.h>

#include <cmath>
#include <iterator>
#include <stdexcept>

namespace toposlam::planning {

namespace ob = ompl::base;
namespace og = ompl::geometric;
using mrpt::math::TPoint2D;

namespace {

const char* const kPlanners[] = {"rrtconnect", "rrtstar", "informedrrtstar", "prmstar", "bitstar"};

ob::PlannerPtr makePlanner(const std::string& name, const ob::SpaceInformationPtr& si) {
    if (name == "rrtconnect")
        return std::make_shared<og::RRTConnect>(si);
    if (name == "rrtstar")
        return std::make_shared<og::RRTstar>(si);
    if (name == "informedrrtstar")
        return std::make_shared<og::InformedRRTstar>(si);
    if (name == "prmstar")
        return std::make_shared<og::PRMstar>(si);
    if (name == "bitstar")
        return std::make_shared<og::BITstar>(si);
    throw std::invalid_argument("unknown planner '" + name + "'");
}

}  // namespace

void OmplPlannerOptions::validate() const {
    bool known = false;
    for (const char* p : kPlanners)
        known = known || planner == p;
    if (!known) {
        throw std::invalid_argument("unknown planner '" + planner +
                                    "' (rrtconnect, rrtstar, informedrrtstar, prmstar, bitstar)");
    }
    if (!(timeLimit > 0) || !std::isfinite(timeLimit))
        throw std::invalid_argument("planning time limit must be positive");
    if (attempts < 1)
        throw std::invalid_argument("planning attempts must be at least 1");
}

const std::vector<std::string>& omplPlannerNames() {
    static const std::vector<std::string> names(std::begin(kPlanners), std::end(kPlanners));
    return names;
}

struct OmplPathPlanner::Impl {
    const TraversabilityGrid& grid;
    OmplPlannerOptions options;
    std::shared_ptr<ob::RealVectorStateSpace> space;
    og::SimpleSetup setup;

    Impl(const TraversabilityGrid& g, const OmplPlannerOptions& o)
        : grid(g), options(o), space(std::make_shared<ob::RealVectorStateSpace>(2)), setup(space) {
        const auto& f = grid.frame();
        ob::RealVectorBounds bounds(2);
        bounds.setLow(0, f.xMin);
        bounds.setHigh(0, f.xMin + f.cols * f.resolution);
        bounds.setLow(1, f.yMin);
        bounds.setHigh(1, f.yMin + f.rows * f.resolution);
        space->setBounds(bounds);
        setup.setStateValidityChecker([this](const ob::State* s) {
            const auto* v = s->as<ob::RealVectorStateSpace::StateType>();
            return grid.isTraversable(v->values[0], v->values[1]);
        });
        // Motions are checked every quarter cell (the resolution is a fraction of the extent).
        setup.getSpaceInformation()->setStateValidityCheckingResolution(0.25 * f.resolution /
                                                                        space->getMaximumExtent());
        setup.setOptimizationObjective(
            std::make_shared<ob::PathLengthOptimizationObjective>(setup.getSpaceInformation()));
        setup.setPlanner(makePlanner(options.planner, setup.getSpaceInformation()));
        setup.setup();
    }

    ob::ScopedState<ob::RealVectorStateSpace> state(const TPoint2D& p) const {
        ob::ScopedState<ob::RealVectorStateSpace> s(space);
        s[0] = p.x;
        s[1] = p.y;
        return s;
    }

    static std::vector<TPoint2D> points(og::PathGeometric& path) {
        std::vector<TPoint2D> out;
        out.reserve(path.getStateCount());
        for (const ob::State* s : path.getStates()) {
            const auto* v = s->as<ob::RealVectorStateSpace::StateType>();
            out.emplace_back(v->values[0], v->values[1]);
        }
        return out;
    }
};

OmplPathPlanner::OmplPathPlanner(const TraversabilityGrid& grid,
                                 const OmplPlannerOptions& options) {
    options.validate();
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);  // OMPL's per-query info lines are noise here
    impl_ = std::make_unique<Impl>(grid, options);
}

OmplPathPlanner::~OmplPathPlanner() = default;

std::optional<std::vector<TPoint2D>> OmplPathPlanner::plan(const TPoint2D& from,
                                                           const TPoint2D& to) {
    og::SimpleSetup& ss = impl_->setup;
    std::optional<std::vector<TPoint2D>> best;
    double bestLength = 0;
    for (int attempt = 0; attempt < impl_->options.attempts; ++attempt) {
        ss.clear();  // forget the previous tree / roadmap
        ss.setStartAndGoalStates(impl_->state(from), impl_->state(to));
        if (ss.solve(impl_->options.timeLimit) != ob::PlannerStatus::EXACT_SOLUTION)
            continue;
        if (impl_->options.simplify)
            ss.simplifySolution();
        og::PathGeometric& path = ss.getSolutionPath();
        if (!best || path.length() < bestLength) {
            bestLength = path.length();
            best = Impl::points(path);
        }
    }
    return best;
}

}  // namespace toposlam::planning
