/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.ros2

import java.util.TreeSet
import org.rsaml.analysis.plan.PlannedFunction
import org.rsaml.analysis.plan.PlannedModule
import org.rsaml.analysis.plan.PlannedPort
import org.rsaml.analysis.plan.Reaction
import org.rsaml.analysis.plan.Release
import org.rsaml.generator.internal.cxx.CxxNames

/**
 * A module's node, the generated base class gen/LAYER/ModuleBase.hpp: its parameters, publishers,
 * subscriptions (subsumption links among them) and timers on the scheduling runtime, the virtual
 * methods the architect's class overrides, and how a release or an arrival runs them. What only a
 * managed (rclcpp_lifecycle) node has, its transitions, is Ros2ManagedNodeTemplate's.
 */
class Ros2NodeTemplate extends Ros2Template {

	val extension CxxNames names
	val extension Ros2Names rosNames
	val Ros2ManagedNodeTemplate managed

	new(Ros2Context context) {
		super(context)
		this.names = context.names
		this.rosNames = context.rosNames
		this.managed = new Ros2ManagedNodeTemplate(context, this)
	}

	def private headersOf(PlannedModule m) {
		val headers = new TreeSet<String>
		for (p : m.ports) {
			headers += p.rosHeader
		}
		for (p : m.inputs) {
			for (l : p.suppressors) {
				headers += l.trigger.rosHeader
			}
		}
		for (p : m.outputs) {
			for (l : p.inhibitors) {
				headers += l.trigger.rosHeader
			}
		}
		headers
	}


	def base(PlannedModule m) '''
		// «banner»
		#pragma once

		#include <atomic>
		#include <cmath>
		#include <cstdint>
		#include <cstdio>
		#include <memory>
		#include <mutex>
		#include <optional>
		#include <stdexcept>
		#include <string>

		#include <rclcpp/rclcpp.hpp>
		«IF m.managed»
			#include <rclcpp_lifecycle/lifecycle_node.hpp>
			#include "rsaml/lifecycle.hpp"
		«ELSE»
			#include "rsaml/scheduling.hpp"
		«ENDIF»
		«FOR h : headersOf(m)»
			#include <«h»>
		«ENDFOR»

		namespace «names.project»::«m.layerId» {

		/**
		 * Node «doc(m.rosNode)»: module «doc(m.qualifiedName)»«described(m.description)»
		 * Timing: «doc(m.timing)».
		 * The generated part: «m.className» (src/«m.layerId»/«m.className».hpp, yours) derives from it.
		 * Topics are relative: the node's namespace (launch argument namespace) prefixes them all. The
		 * model's times are parameters in the model's units (the name ends with the unit: period_ms),
		 * with the model's values as defaults (config/«pkg».params.yaml sets them); QoS can be
		 * overridden with the qos_overrides.<topic> parameters; timers run on the node's clock
		 * (use_sim_time).«IF m.managed»
		 * A managed node (rclcpp_lifecycle): created unconfigured; configure creates its publishers and
		 * subscriptions, activate starts its timers and lets it publish and react (what arrives before is
		 * dropped), deactivate stops both, cleanup and shutdown release them. The launch files activate it.«ENDIF»
		 */
		class «m.baseName» : public ::«names.project»::rsaml_ros2::«IF m.managed»ScheduledLifecycleNode«ELSE»ScheduledNode«ENDIF» {
		 public:
		  explicit «m.baseName»(const rclcpp::NodeOptions& options)
		      : ::«names.project»::rsaml_ros2::«IF m.managed»ScheduledLifecycleNode«ELSE»ScheduledNode«ENDIF»(«str(m.rosNode)», options, «str(m.qualifiedName)», «m.core») {
		    «parameters(m)»
		    «IF !m.inputs.empty || !context.linksOf(m).empty»
		    	// data arrivals (entry ports, link triggers) on an executor thread of their own at priority 0 of
		    	// the analysis, the lowest real-time priority, below every release
		    	this->rsaml_data_group();
		    «ENDIF»
		    «IF m.managed»
		    	«managed.construction(m)»
		    «ELSE»
		    	«entities(m)»
		    	«timers(m)»
		    «ENDIF»
		    «IF m.reactive»
		    	// reactions: from the arrival that starts one to its completion, due within «m.reaction.deadlineNs» ns (0: none),
		    	// modeled to take «m.reaction.costNs» ns; «boundComment(m.reaction)».
		    	this->rsaml_measure_reactions(«str(m.reaction.label)», «m.reaction.deadlineNs», «m.reaction.costNs», «context.bounds.of(m.reaction).responseNs»);
		    	«IF context.bounds.aperiodic(m.reaction)»
		    		// aperiodic reactions, which the analysis excludes: the node's data at the default priority, below every
		    		// real-time thread, so that more data than the node can react to takes no real-time time from the releases
		    		this->rsaml_data_unbounded();
		    	«ENDIF»
		    «ENDIF»
		  }
		  «IF !m.inputs.empty»

		  	// Entry ports: the latest message received, shared with the middleware and every other
		  	// subscriber, not copied (null until the first arrives).
		  	«FOR p : m.inputs»
		  		«p.rosType»::ConstSharedPtr «p.inName»;
		  	«ENDFOR»
		  «ENDIF»
		  «IF !m.outputs.empty»

		  	// Output ports: set them; they are published after each activation (or call publish_outputs()), a copy of
		  	// each value, which the port keeps. To hand a message over without a copy, send it (send_<port>, below).
		  	«FOR p : m.outputs»
		  		«p.rosType» «p.outName»;
		  	«ENDFOR»
		  «ENDIF»

		 protected:
		  «FOR f : m.functions»
		  	/** Function «doc(f.name)» («doc(f.timing)») */
		  	virtual void «f.method»() {
		  	  «FOR a : f.inlineActions»
		  	  	«a.method»();
		  	  «ENDFOR»
		  	}
		  	«FOR a : f.actions»
		  		/** Action «doc(a.name)» («doc(a.timing)») */
		  		virtual void «a.method»() {}
		  	«ENDFOR»
		  «ENDFOR»
		  «FOR p : m.inputs»
		  	/** Called on each message at «doc(p.name)», before the node reacts («p.inName» holds it too). */
		  	virtual void «p.onName»(const «p.rosType»& message) { (void)message; }
		  «ENDFOR»
		  «FOR p : m.outputs»
		  	«sendDoc(m, p)»
		  	void «p.sendName»(std::unique_ptr<«p.rosType»> message) {
		  	  if (!message) {
		  	    throw std::invalid_argument("node «m.rosNode»: «p.sendName» was given no message (a null pointer)");
		  	  }
		  	  «IF m.managed»
		  	  	«managed.markSent(p)»
		  	  «ELSE»
		  	  	«p.sentName»_ = true;
		  	  «ENDIF»
		  	  «IF p.inhibitors.empty»
		  	  	«p.pubName»_->publish(std::move(message));
		  	  «ELSE»
		  	  	if («unblocked(p)») {
		  	  	  «p.pubName»_->publish(std::move(message));
		  	  	}
		  	  «ENDIF»
		  	}
		  «ENDFOR»
		  /**
		   * Publishes every output port (unless an inhibitor blocks it«IF m.managed», or the node is not active«ENDIF», or the
		   * port's send method sent a message since the last call): a copy of the port's value, which it keeps, handed
		   * to the middleware as a unique message that the subscriptions of the same container then share without
		   * copying it again (intra-process communication).
		   */
		  virtual void publish_outputs() {
		    «IF m.managed»
		    	«managed.inactiveReturn»
		    «ENDIF»
		    «FOR p : m.outputs»
		    	if (!«p.sentName»_.exchange(false)«IF !p.inhibitors.empty» && «unblocked(p)»«ENDIF») {
		    	  «p.pubName»_->publish(std::make_unique<«p.rosType»>(«p.outName»));
		    	}
		    «ENDFOR»
		  }
		  «IF m.managed»

		  	«managed.transitions(m)»
		  «ENDIF»

		 private:
		  /** A time parameter in nanoseconds: from 1 ns to 2^60 ns, as the generated code counts time. */
		  static std::int64_t nanoseconds(const char* parameter, double value, double unit_ns) {
		    const double ns = value * unit_ns;
		    if (!std::isfinite(ns) || !(ns >= 0.5) || ns > 1152921504606846976.0) {
		      char given[32];
		      std::snprintf(given, sizeof given, "%g", value);
		      throw ::«names.project»::rsaml_ros2::UsageError(
		          std::string("node «m.rosNode»: parameter ") + parameter + " is " + given
		          + ": it must be a positive time of at least 1 ns and at most 2^60 ns, in the unit its name"
		          + " ends with; set it so in the parameters file (config/«pkg».params.yaml, or params_file:=)");
		    }
		    return std::llround(ns);
		  }

		  «IF m.managed»
		  	«managed.releaseEntities(m)»

		  «ENDIF»
		  /** Whether a subsumption link is active now (on the node's clock). */
		  bool active(const std::optional<rclcpp::Time>& until) { return until && this->now() < *until; }

		  /** Whether `interval` has passed since `last` (on the node's clock); if so, `last` becomes now. */
		  bool due(std::optional<rclcpp::Time>& last, std::int64_t interval) {
		    const rclcpp::Time now = this->now();
		    if (last && now - *last < rclcpp::Duration::from_nanoseconds(interval)) {
		      return false;
		    }
		    last = now;
		    return true;
		  }
		  «FOR r : m.releases»

		  	void «r.method»() {
		  	  «IF m.managed»
		  	  	«managed.inactiveReturn»
		  	  «ENDIF»
		  	  «release(r)»
		  	  publish_outputs();
		  	}
		  «ENDFOR»
		  «FOR p : m.inputs»

		  	void «p.receiveName»(const «p.rosType»::ConstSharedPtr& message, bool replacing) {
		  	  «IF !p.suppressors.empty»
		  	  	if (!replacing && («FOR l : p.suppressors SEPARATOR ' || '»active(link_«l.stem»_until_)«ENDFOR»)) {
		  	  	  return;  // suppressed
		  	  	}
		  	  «ELSE»
		  	  	(void)replacing;
		  	  «ENDIF»
		  	  «p.inName» = message;
		  	  «p.onName»(*message);
		  	  «IF m.reactive»
		  	  	«m.reactMethod»();
		  	  «ENDIF»
		  	}
		  «ENDFOR»
		  «IF m.reactive»

		  	void «m.reactMethod»() {
		  	  «IF m.reactionIntervalNs > 0»
		  	  	if (!due(last_reaction_, reaction_interval_)) {
		  	  	  return;  // «IF m.cycleBoundNs > 0»at most once per wave of the cycle«ELSE»sporadic: not sooner than its period«ENDIF»
		  	  	}
		  	  «ENDIF»
		  	  this->rsaml_run_reaction([this] {
		  	    «FOR f : m.stepFunctions»
		  	    	«callFunction(f)»
		  	    «ENDFOR»
		  	    publish_outputs();
		  	  });
		  	}
		  «ENDIF»

		  «FOR r : m.releases»
		  	std::int64_t «r.timerMember»_period_;
		  «ENDFOR»
		  «FOR f : m.stepFunctions.filter[minIntervalNs > 0]»
		  	std::int64_t «f.lastRunMember»_interval_;
		  	std::optional<rclcpp::Time> «f.lastRunMember»;
		  «ENDFOR»
		  «IF m.reactive && m.reactionIntervalNs > 0»
		  	std::int64_t reaction_interval_;
		  	std::optional<rclcpp::Time> last_reaction_;
		  «ENDIF»
		  «FOR p : m.outputs»
		  	«IF m.managed»rclcpp_lifecycle::LifecyclePublisher«ELSE»rclcpp::Publisher«ENDIF»<«p.rosType»>::SharedPtr «p.pubName»_;
		  	std::atomic<bool> «p.sentName»_{false};
		  «ENDFOR»
		  «FOR p : m.inputs»
		  	rclcpp::Subscription<«p.rosType»>::SharedPtr «p.subName»_;
		  «ENDFOR»
		  «FOR l : context.linksOf(m)»
		  	rclcpp::Subscription<«l.trigger.rosType»>::SharedPtr link_«l.stem»_sub_;
		  	std::int64_t link_«l.stem»_duration_;
		  	std::optional<rclcpp::Time> link_«l.stem»_until_;
		  «ENDFOR»
		  «FOR r : m.releases»
		  	rclcpp::TimerBase::SharedPtr «r.timerMember»_;
		  «ENDFOR»
		  «IF m.managed»
		  	«managed.members(m)»
		  «ENDIF»
		};

		}  // namespace «names.project»::«m.layerId»
	'''

	/** Declares the node's parameters (in its constructor, managed or not). */
	def private parameters(PlannedModule m) '''
		«FOR r : m.releases»
			«r.timerMember»_period_ = «declare(context.periodParameter(r))»;
		«ENDFOR»
		«FOR f : m.stepFunctions.filter[minIntervalNs > 0]»
			«f.lastRunMember»_interval_ = «declare(context.intervalParameter(f))»;
		«ENDFOR»
		«IF m.reactive && m.reactionIntervalNs > 0»
			reaction_interval_ = «declare(context.reactionParameter(m))»;
		«ENDIF»
		«FOR l : context.linksOf(m)»
			link_«l.stem»_duration_ = «declare(context.durationParameter(l))»;
		«ENDFOR»
	'''

	/** Creates the publishers and subscriptions: in the constructor of a plain node, when a managed node is configured. */
	def entities(PlannedModule m) '''
		rclcpp::PublisherOptions publisher_options;
		publisher_options.qos_overriding_options = rclcpp::QosOverridingOptions::with_default_policies();
		rclcpp::SubscriptionOptions subscription_options;
		subscription_options.qos_overriding_options = rclcpp::QosOverridingOptions::with_default_policies();
		«IF !m.inputs.empty || !context.linksOf(m).empty»
			subscription_options.callback_group = this->rsaml_data_group();
		«ENDIF»
		(void)publisher_options;
		(void)subscription_options;
		«FOR p : m.outputs»
			«p.pubName»_ = this->create_publisher<«p.rosType»>(«str(p.topic)», «p.qos», publisher_options);
		«ENDFOR»
		«FOR p : m.inputs»
			«p.subName»_ = this->create_subscription<«p.rosType»>(
			    «str(p.topic)», «p.qos»,
			    [this, port = «IF m.managed»«p.subName»_port_«ELSE»this->rsaml_add_arrivals(«str(p.name)»)«ENDIF»](«p.rosType»::ConstSharedPtr message) {
			      «IF m.managed»
			      	«managed.inactiveReturn»
			      «ENDIF»
			      this->rsaml_run_arrival(port, [&] { this->«p.receiveName»(message, false); });
			    },
			    subscription_options);
		«ENDFOR»
		«FOR l : context.linksOf(m)»
			// «IF l.inhibitor»Inhibitor«ELSE»Suppressor«ENDIF» «doc(l.qualifiedName)», triggered by «IF l.trigger.assertsOnlyWhenTrue»each true on «ELSE»each message on «ENDIF»«doc(l.trigger.qualifiedName)».
			link_«l.stem»_sub_ = this->create_subscription<«l.trigger.rosType»>(
			    «str(l.trigger.topic)», «l.trigger.qos»,
			    [this, port = «IF m.managed»link_«l.stem»_port_«ELSE»this->rsaml_add_arrivals(«str(l.qualifiedName)»)«ENDIF»](«l.trigger.rosType»::ConstSharedPtr message) {
			      «IF m.managed»
			      	«managed.inactiveReturn»
			      «ENDIF»
			      this->rsaml_run_arrival(port, [&] {
			        «IF l.trigger.assertsOnlyWhenTrue»
			        	if (!message->data) {
			        	  return;  // only true asserts the link: false neither starts nor ends it, nor is delivered
			        	}
			        «ENDIF»
			        link_«l.stem»_until_ = this->now() + rclcpp::Duration::from_nanoseconds(link_«l.stem»_duration_);
			        «IF l.deliversData»
			        	this->«l.target.receiveName»(message, true);
			        «ELSE»
			        	(void)message;
			        «ENDIF»
			      });
			    },
			    subscription_options);
		«ENDFOR»
	'''
	/**
	 * Creates the timers of the releases: in the constructor of a plain node, when a managed node is
	 * activated (its releases and their callback groups exist from its constructor on, so that their
	 * executor threads serve the timers whenever they are created).
	 */
	def timers(PlannedModule m) '''
		«FOR r : m.releases»
			// «r.kind.name.toLowerCase» «doc(r.label)» every «r.periodNs» ns («r.why»): rank «r.rank»«IF r.edf» (EDF: SCHED_DEADLINE)«ENDIF», deadline «r.deadlineNs» ns, cost «r.costNs» ns;
			// «context.boundComment(r)»
			«IF m.managed»
				«r.timerMember»_ = this->rsaml_add_timer(«r.timerMember»_release_, «r.timerMember»_period_, [this] { this->«r.method»(); });
			«ELSE»
				«r.timerMember»_ = this->rsaml_add_timer(
				    this->rsaml_add_release(«str(r.label)», «r.rank», «IF r.policy == org.rsaml.model.SchedulingPolicy.RR»true«ELSE»false«ENDIF», «r.deadlineNs», «r.costNs»,
				                            «r.timerMember»_period_, «context.bounds.of(r).responseNs», «IF r.edf»true«ELSE»false«ENDIF»),
				    «r.timerMember»_period_, [this] { this->«r.method»(); });
			«ENDIF»
		«ENDFOR»
	'''


	/**
	 * The doc comment of an output port's send method: what the next publish of the ports does after a send, and
	 * where that publish comes for this node (a release's end, a reaction's end; not after a periodic node's input
	 * handlers, which no publish follows).
	 */
	def private sendDoc(PlannedModule m, PlannedPort p) '''
		/**
		 * Publishes `message` (not null) at output port «doc(p.name)» now, handed to the middleware without a copy: the
		 * subscriptions of the same container get this very object (intra-process communication). An inhibitor active
		 * now«IF m.managed», or the node not active,«ENDIF» drops it, as it would the port's value. The port's value
		 * («p.outName») is left as it is, and the next publish of the ports (publish_outputs()) skips the port, so that no
		 * older value follows the message; the publishes after it publish the port's value again unless the node sends again.
		«IF !m.releases.empty»
			 * Each release of the node (its timers running its actions or functions) ends with that publish.
		«ENDIF»
		«IF m.reactive»
			 * An input handler is followed by the node's reaction, which ends with that publish«IF m.reactionIntervalNs > 0» (a reaction not yet
			 * due does not run, nor publish: then it is the next reaction's or release's)«ENDIF».
		«ELSEIF !m.inputs.empty»
			 * The input handlers run on each arrival and no publish follows them (the node does not react to data): a send
			 * from one is published at once, and the publish that ends the node's next release skips the port.
		«ENDIF»
		«IF m.managed»
			 * Deactivating the node forgets a send that publish has not yet followed: the first publish after the node is
			 * activated again publishes the port's value.
		«ENDIF»
		 */
	'''

	/** Whether no inhibitor of an output port is active now (a C++ condition). */
	def private unblocked(PlannedPort p) '''«FOR l : p.inhibitors SEPARATOR ' && '»!active(link_«l.stem»_until_)«ENDFOR»'''

	/** What the analysis says of a module's reactions' response time, for a comment. */
	def private boundComment(Reaction x) {
		val bound = context.bounds.of(x)
		if (bound.responseNs >= 0) '''analysed worst-case response «bound.responseNs» ns («doc(bound.why)»)'''
		else '''no analysed bound: «doc(bound.why)»'''
	}

	def private release(Release r) {
		switch (r.kind) {
			case FUNCTION: '''«r.function.method»();'''
			case ACTION: '''«r.action.method»();'''
			default: '''
				«FOR f : r.module.stepFunctions»
					«callFunction(f)»
				«ENDFOR»
			'''
		}
	}

	def private callFunction(PlannedFunction f) '''
		«IF f.minIntervalNs > 0»
			if (due(«f.lastRunMember», «f.lastRunMember»_interval_)) {
			  «f.method»();
			}
		«ELSE»
			«f.method»();
		«ENDIF»
	'''

	/** Declares a time parameter, in its unit, and holds it in nanoseconds. */
	def private declare(Ros2TimeParameter p) '''nanoseconds(«str(p.name)», this->declare_parameter<double>(«str(p.name)», «p.value»), «p.nanosPerUnit»)'''
}
