/* mrpt_fog_heading: the heading pipeline of a vehicle with a FOG. */
#include <mrpt/core/Clock.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationRobotPose.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog_heading/FogOdometryRawlog.h>

#include <cmath>
#include <deque>
#include <stdexcept>

namespace mrpt_fog::heading
{
std::string labelKey(const mrpt::serialization::CSerializable& obj)
{
	std::string key = obj.GetRuntimeClass()->className;
	if (const auto* o = dynamic_cast<const mrpt::obs::CObservation*>(&obj)) key += " '" + o->sensorLabel + "'";
	return key;
}

void countLabels(const mrpt::serialization::CSerializable& obj, LabelCounts& counts)
{
	counts[labelKey(obj)]++;
	if (const auto* sf = dynamic_cast<const mrpt::obs::CSensoryFrame*>(&obj))
		for (const auto& o : *sf) counts[labelKey(*o)]++;
	else if (const auto* acts = dynamic_cast<const mrpt::obs::CActionCollection*>(&obj))
		for (std::size_t i = 0; i < acts->size(); i++) counts[labelKey(acts->get(i))]++;
}

namespace
{
/** A truth read from its own rawlog as far as it is needed (held-back truth). */
class TruthFile
{
   public:
	TruthFile(const std::string& path, const std::string& label) : reader_(path), label_(label) {}
	/** Feeds the truth poses up to the first one after t_s. */
	void feedTo(double t_s, TruthComparison& a, TruthComparison& b)
	{
		while (!done_ && !(last_t_ > t_s))
		{
			const auto obj = reader_.next();
			if (!obj)
			{
				done_ = true;
				return;
			}
			const auto take = [&](const mrpt::obs::CObservation::Ptr& o) {
				const auto gt = std::dynamic_pointer_cast<mrpt::obs::CObservationRobotPose>(o);
				if (!gt || gt->sensorLabel != label_) return;
				const double t = mrpt::Clock::toDouble(gt->timestamp);
				const auto& m = gt->pose.mean;
				a.addTruth(t, m.x(), m.y(), m.yaw());
				b.addTruth(t, m.x(), m.y(), m.yaw());
				last_t_ = std::max(last_t_, t);
				n_++;
			};
			if (auto o = std::dynamic_pointer_cast<mrpt::obs::CObservation>(obj)) take(o);
			else if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(obj))
				for (const auto& so : *sf) take(so);
		}
	}
	std::size_t poses() const { return n_; }

   private:
	RawlogObjectReader reader_;
	std::string label_;
	bool done_ = false;
	double last_t_ = -std::numeric_limits<double>::infinity();
	std::size_t n_ = 0;
};

/** The wheel odometry an object holds, waiting for its FOG heading. */
struct Waiting
{
	double t_s = 0;
	mrpt::obs::CObservationOdometry::Ptr odometry;  //!< observations: rewritten in place
	mrpt::obs::CActionRobotMovement2D::Ptr action;  //!< actions: rewritten in place
	std::size_t item = 0;  //!< its object's position in the output queue (global index)
};

class Rewriter
{
   public:
	Rewriter(const std::string& input, const std::string& output, const Calibration* cal, const FogOdometryOptions& o)
		: in_path_(input), o_(o), fog_cmp_(true, o.compare_s), wheel_cmp_(true, o.compare_s)
	{
		FogSeries header;
		{
			FogLogReader first(input, o.fog_label);  // the FOG's layout and metadata (its first sample)
			header = first.header();
		}
		PipelineOptions popt = o.pipeline;
		if (!std::isfinite(popt.latitude_deg))
		{
			const auto lat = latitudeOf(header);
			if (!lat)
				throw std::runtime_error(input + ": no latitude_deg in the FOG's metadata; give the drive's latitude "
												 "(the Earth rate depends on it)");
			popt.latitude_deg = *lat;
		}
		report_.latitude_deg = popt.latitude_deg;
		pipe_ = std::make_unique<HeadingPipeline>(header, popt, cal);
		report_.earth = pipe_->earthRate();
		samples_ = std::make_unique<FogObservationSamples>(header, input);
		if (!o.truth_path.empty()) truth_file_ = std::make_unique<TruthFile>(o.truth_path, o.truth_label);
		reader_ = std::make_unique<RawlogObjectReader>(input);
		writer_ = std::make_unique<RawlogObjectWriter>(output);
	}

	FogOdometryReport run()
	{
		std::size_t k = 0;
		while (auto obj = reader_->next())
		{
			countLabels(*obj, report_.counts_in);
			queue_.push_back({obj, 0});
			const std::size_t item = base_ + queue_.size() - 1;
			if (auto o = std::dynamic_pointer_cast<mrpt::obs::CObservation>(obj)) observation(o, item);
			else if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(obj))
			{
				for (const auto& so : *sf) observation(so, item);
			}
			else if (auto acts = std::dynamic_pointer_cast<mrpt::obs::CActionCollection>(obj))
				actions(*acts, item);
			drain();
			if (o_.progress && ++k % 4096 == 0) o_.progress(reader_->fileBytesRead(), reader_->fileBytes());
		}
		pipe_->finish();
		drain();
		if (!queue_.empty()) throw std::logic_error("fog-odometry: objects left waiting at the end");
		writer_->close();
		report_.format = reader_->format();
		report_.objects_in = reader_->objectsRead();
		report_.objects_out = writer_->objectsWritten();
		report_.pipeline = pipe_->counters();
		if (const auto* c = pipe_->compensationCounters()) report_.compensation = *c;
		report_.screening = pipe_->screeningCounters();
		if (auto* sc = dynamic_cast<StandstillCorrection*>(pipe_->rateCorrection()))
		{
			sc->finish();
			report_.field_refinement = true;
			if (const auto* f = sc->refiner())
			{
				report_.standstill_updates = f->updates();
				report_.offset_applied = f->applied();
				report_.offset_dph = f->filter().offset_dph();
				report_.offset_sigma_dph = f->filter().offset_sigma_dph();
			}
		}
		if (truth_file_) truth_file_->feedTo(std::numeric_limits<double>::infinity(), fog_cmp_, wheel_cmp_);
		if (any_truth_ || (truth_file_ && truth_file_->poses() > 0))
		{
			report_.fog_vs_truth = fog_cmp_.finish();
			report_.wheels_vs_truth = wheel_cmp_.finish();
		}
		return report_;
	}

   private:
	struct Item
	{
		mrpt::serialization::CSerializable::Ptr obj;
		std::size_t waiting;
	};

	void observation(const mrpt::obs::CObservation::Ptr& o, std::size_t item)
	{
		if (auto f = std::dynamic_pointer_cast<CObservationFOG>(o); f && f->sensorLabel == o_.fog_label)
		{
			samples_->toSample(*f, reader_->objectsRead() - 1, x_);
			pipe_->addFog(x_);
		}
		else if (auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(o);
				 odo && odo->sensorLabel == o_.odometry_label)
		{
			const double t = mrpt::Clock::toDouble(odo->timestamp);
			wheel(t, odo->odometry.x(), odo->odometry.y(), odo->odometry.phi());
			if (addOdometry(t, odo->odometry.x(), odo->odometry.y(), odo->odometry.phi()))
			{
				waiting_.push_back({t, odo, nullptr, item});
				queue_[item - base_].waiting++;
			}
		}
		else if (auto gt = std::dynamic_pointer_cast<mrpt::obs::CObservationRobotPose>(o);
				 gt && o_.truth_path.empty() && gt->sensorLabel == o_.truth_label)
		{
			const auto& m = gt->pose.mean;
			const double t = mrpt::Clock::toDouble(gt->timestamp);
			fog_cmp_.addTruth(t, m.x(), m.y(), m.yaw());
			wheel_cmp_.addTruth(t, m.x(), m.y(), m.yaw());
			any_truth_ = true;
		}
	}

	void actions(mrpt::obs::CActionCollection& acts, std::size_t item)
	{
		auto mv = acts.getActionByClass<mrpt::obs::CActionRobotMovement2D>();
		if (!mv) return;
		if (mv->timestamp == INVALID_TIMESTAMP)
			throw std::runtime_error(in_path_ + ": object #" + std::to_string(reader_->objectsRead() - 1) +
									 ": a CActionRobotMovement2D without a timestamp (its time is needed to take the "
									 "FOG heading at it)");
		wheel_pose_ = wheel_pose_ + mv->rawOdometryIncrementReading;
		const double t = mrpt::Clock::toDouble(mv->timestamp);
		wheel(t, wheel_pose_.x(), wheel_pose_.y(), wheel_pose_.phi());
		if (addOdometry(t, wheel_pose_.x(), wheel_pose_.y(), wheel_pose_.phi()))
		{
			waiting_.push_back({t, nullptr, mv, item});
			queue_[item - base_].waiting++;
		}
	}

	/** An estimate is held only once a truth was met (none before it can be compared; without a
	 * truth nothing is held: flat memory). */
	bool comparing() const { return any_truth_ || (truth_file_ && truth_file_->poses() > 0); }

	void wheel(double t, double x, double y, double phi)
	{
		if (truth_file_) truth_file_->feedTo(t, fog_cmp_, wheel_cmp_);
		if (comparing()) wheel_cmp_.addEstimate(t, x, y, phi);
	}

	/** true when the pipeline took the sample (it then gives a pose for it). */
	bool addOdometry(double t, double x, double y, double phi)
	{
		const std::size_t skipped = pipe_->counters().odometry_skipped;
		pipe_->addOdometry(t, x, y, phi);
		if (pipe_->counters().odometry_skipped != skipped || !pipe_->aligned())
		{
			report_.odometry_unchanged++;
			return false;
		}
		return true;
	}

	void drain()
	{
		DeadReckonedPose p;
		while (pipe_->popPose(p))
		{
			if (waiting_.empty() || waiting_.front().t_s != p.t_s)
				throw std::logic_error("fog-odometry: a pose for no waiting odometry");
			const Waiting w = waiting_.front();
			waiting_.pop_front();
			if (truth_file_) truth_file_->feedTo(p.t_s, fog_cmp_, wheel_cmp_);
			if (comparing()) fog_cmp_.addEstimate(p.t_s, p.x_m, p.y_m, p.heading_rad);
			if (w.odometry)
			{
				w.odometry->odometry = mrpt::poses::CPose2D(p.x_m, p.y_m, p.heading_rad);
				report_.odometry_rewritten++;
			}
			else if (last_pose_)  // the first action (the alignment) keeps its increment
			{
				const mrpt::poses::CPose2D a(last_pose_->x_m, last_pose_->y_m, last_pose_->heading_rad);
				const mrpt::poses::CPose2D b(p.x_m, p.y_m, p.heading_rad);
				const auto model = p.source == HeadingSource::Gyro ? o_.motion.toMrpt(p.t_s - last_pose_->t_s)
																   : wheelMotionModel();
				w.action->computeFromOdometry(b - a, model);
				report_.odometry_rewritten++;
			}
			else
				report_.odometry_unchanged++;
			last_pose_ = p;
			queue_[w.item - base_].waiting--;
		}
		while (!queue_.empty() && queue_.front().waiting == 0)
		{
			countLabels(*queue_.front().obj, report_.counts_out);
			writer_->write(*queue_.front().obj);
			queue_.pop_front();
			base_++;
		}
	}

	std::string in_path_;
	FogOdometryOptions o_;
	std::unique_ptr<HeadingPipeline> pipe_;
	std::unique_ptr<FogObservationSamples> samples_;
	std::unique_ptr<RawlogObjectReader> reader_;
	std::unique_ptr<RawlogObjectWriter> writer_;
	std::unique_ptr<TruthFile> truth_file_;
	TruthComparison fog_cmp_, wheel_cmp_;
	bool any_truth_ = false;
	FogSample x_;
	std::deque<Item> queue_;
	std::size_t base_ = 0;  // global index of queue_.front()
	std::deque<Waiting> waiting_;
	std::optional<DeadReckonedPose> last_pose_;
	mrpt::poses::CPose2D wheel_pose_;
	FogOdometryReport report_;
};
}  // namespace

FogOdometryReport writeFogOdometry(const std::string& input, const std::string& output, const Calibration* cal,
								   const FogOdometryOptions& options)
{
	Rewriter r(input, output, cal, options);
	return r.run();
}

}  // namespace mrpt_fog::heading
