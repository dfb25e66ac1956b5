package org.rsaml.text.parser.antlr.internal;

import org.eclipse.xtext.*;
import org.eclipse.xtext.parser.*;
import org.eclipse.xtext.parser.impl.*;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.common.util.Enumerator;
import org.eclipse.xtext.parser.antlr.AbstractInternalAntlrParser;
import org.eclipse.xtext.parser.antlr.XtextTokenStream;
import org.eclipse.xtext.parser.antlr.XtextTokenStream.HiddenTokens;
import org.eclipse.xtext.parser.antlr.AntlrDatatypeRuleToken;
import org.rsaml.text.services.RsamlTextGrammarAccess;



import org.antlr.runtime.*;
import java.util.Stack;
import java.util.List;
import java.util.ArrayList;

@SuppressWarnings("all")
public class InternalRsamlTextParser extends AbstractInternalAntlrParser {
    public static final String[] tokenNames = new String[] {
        "<invalid>", "<EOR>", "<DOWN>", "<UP>", "RULE_STRING", "RULE_ID", "RULE_NUMBER", "RULE_ML_COMMENT", "RULE_SL_COMMENT", "RULE_WS", "RULE_ANY_OTHER", "'architecture'", "'{'", "'category'", "'declaredLayers'", "'lifecycle'", "'packages'", "'}'", "'description'", "'unit'", "'type'", "'execType'", "'period'", "'deadline'", "'wcet'", "'layer'", "'level'", "'maxExecTime'", "'module'", "'sensors'", "','", "'actuators'", "'function'", "'synchroType'", "'schedPolicy'", "'otherPolicy'", "'action'", "'rtAction'", "'start'", "'input'", "'output'", "'dataType'", "'messageType'", "'topic'", "'connect'", "'->'", "'inhibitor'", "'trigger'", "'target'", "'duration'", "'suppressor'", "'sensor'", "'kind'", "'actuator'", "'mission'", "'goal'", "'priority'", "'plan'", "'achieves'", "'activity'", "'actions'", "'supervisor'", "'plans'", "'realisedBy'", "'order'", "'issuer'", "'receiver'", "'requests'", "'database'", "'knowledge'", "'usedBy'", "'processor'", "'core'", "'host'", "'linkLatency'", "'modules'", "'latency'", "'from'", "'to'", "'via'", "'maxLatency'", "'.'", "'centralized'", "'hierarchical'", "'behavioral'", "'hybrid'", "'other'", "'simple'", "'realTime'", "'periodic'", "'sporadic'", "'aperiodic'", "'ns'", "'us'", "'ms'", "'s'", "'synchronous'", "'asynchronous'", "'FIFO'", "'SJF'", "'RR'", "'RM'", "'DM'", "'EDF'", "'LLF'", "'OTHER'", "'numeric'", "'alphanumeric'", "'boolean'", "'structured'", "'reactionTime'", "'dataAge'", "'plain'", "'managed'", "'single'", "'perLayer'", "'perProcessor'", "'NaN'", "'Infinity'", "'-'"
    };
    public static final int T__50=50;
    public static final int T__59=59;
    public static final int T__55=55;
    public static final int T__56=56;
    public static final int T__57=57;
    public static final int T__58=58;
    public static final int T__51=51;
    public static final int T__52=52;
    public static final int T__53=53;
    public static final int T__54=54;
    public static final int T__60=60;
    public static final int T__61=61;
    public static final int RULE_ID=5;
    public static final int T__66=66;
    public static final int RULE_ML_COMMENT=7;
    public static final int T__67=67;
    public static final int T__68=68;
    public static final int T__69=69;
    public static final int T__62=62;
    public static final int T__63=63;
    public static final int T__64=64;
    public static final int T__65=65;
    public static final int T__37=37;
    public static final int T__38=38;
    public static final int T__39=39;
    public static final int T__33=33;
    public static final int T__34=34;
    public static final int T__35=35;
    public static final int T__36=36;
    public static final int T__30=30;
    public static final int T__31=31;
    public static final int T__32=32;
    public static final int T__48=48;
    public static final int T__49=49;
    public static final int T__44=44;
    public static final int T__45=45;
    public static final int T__46=46;
    public static final int T__47=47;
    public static final int T__40=40;
    public static final int T__41=41;
    public static final int T__42=42;
    public static final int T__43=43;
    public static final int T__91=91;
    public static final int T__100=100;
    public static final int T__92=92;
    public static final int T__93=93;
    public static final int T__102=102;
    public static final int T__94=94;
    public static final int T__101=101;
    public static final int T__90=90;
    public static final int T__19=19;
    public static final int T__15=15;
    public static final int T__16=16;
    public static final int T__17=17;
    public static final int T__18=18;
    public static final int T__11=11;
    public static final int T__99=99;
    public static final int T__12=12;
    public static final int T__13=13;
    public static final int T__14=14;
    public static final int T__95=95;
    public static final int T__96=96;
    public static final int T__97=97;
    public static final int T__98=98;
    public static final int T__26=26;
    public static final int T__27=27;
    public static final int T__28=28;
    public static final int T__29=29;
    public static final int T__22=22;
    public static final int T__23=23;
    public static final int T__24=24;
    public static final int T__25=25;
    public static final int T__20=20;
    public static final int T__21=21;
    public static final int T__70=70;
    public static final int T__71=71;
    public static final int T__72=72;
    public static final int RULE_STRING=4;
    public static final int RULE_SL_COMMENT=8;
    public static final int T__77=77;
    public static final int T__119=119;
    public static final int T__78=78;
    public static final int T__118=118;
    public static final int T__79=79;
    public static final int T__73=73;
    public static final int T__115=115;
    public static final int EOF=-1;
    public static final int T__74=74;
    public static final int T__114=114;
    public static final int T__75=75;
    public static final int T__117=117;
    public static final int T__76=76;
    public static final int T__116=116;
    public static final int T__80=80;
    public static final int T__111=111;
    public static final int T__81=81;
    public static final int T__110=110;
    public static final int T__82=82;
    public static final int T__113=113;
    public static final int T__83=83;
    public static final int T__112=112;
    public static final int RULE_WS=9;
    public static final int RULE_ANY_OTHER=10;
    public static final int RULE_NUMBER=6;
    public static final int T__88=88;
    public static final int T__108=108;
    public static final int T__89=89;
    public static final int T__107=107;
    public static final int T__109=109;
    public static final int T__84=84;
    public static final int T__104=104;
    public static final int T__85=85;
    public static final int T__103=103;
    public static final int T__86=86;
    public static final int T__106=106;
    public static final int T__87=87;
    public static final int T__105=105;

    // delegates
    // delegators


        public InternalRsamlTextParser(TokenStream input) {
            this(input, new RecognizerSharedState());
        }
        public InternalRsamlTextParser(TokenStream input, RecognizerSharedState state) {
            super(input, state);
             
        }
        

    public String[] getTokenNames() { return InternalRsamlTextParser.tokenNames; }
    public String getGrammarFileName() { return "InternalRsamlText.g"; }



     	private RsamlTextGrammarAccess grammarAccess;

        public InternalRsamlTextParser(TokenStream input, RsamlTextGrammarAccess grammarAccess) {
            this(input);
            this.grammarAccess = grammarAccess;
            registerRules(grammarAccess.getGrammar());
        }

        @Override
        protected String getFirstRuleName() {
        	return "Architecture";
       	}

       	@Override
       	protected RsamlTextGrammarAccess getGrammarAccess() {
       		return grammarAccess;
       	}




    // $ANTLR start "entryRuleArchitecture"
    // InternalRsamlText.g:65:1: entryRuleArchitecture returns [EObject current=null] : iv_ruleArchitecture= ruleArchitecture EOF ;
    public final EObject entryRuleArchitecture() throws RecognitionException {
        EObject current = null;

        EObject iv_ruleArchitecture = null;


        try {
            // InternalRsamlText.g:65:53: (iv_ruleArchitecture= ruleArchitecture EOF )
            // InternalRsamlText.g:66:2: iv_ruleArchitecture= ruleArchitecture EOF
            {
             newCompositeNode(grammarAccess.getArchitectureRule()); 
            pushFollow(FOLLOW_1);
            iv_ruleArchitecture=ruleArchitecture();

            state._fsp--;

             current =iv_ruleArchitecture; 
            match(input,EOF,FOLLOW_2); 

            }

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "entryRuleArchitecture"


    // $ANTLR start "ruleArchitecture"
    // InternalRsamlText.g:72:1: ruleArchitecture returns [EObject current=null] : ( () otherlv_1= 'architecture' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'category' ( (lv_category_6_0= ruleArchitectureCategory ) ) ) | (otherlv_7= 'declaredLayers' ( (lv_declaredLayers_8_0= ruleInteger ) ) ) | (otherlv_9= 'lifecycle' ( (lv_lifecycle_10_0= ruleNodeLifecycle ) ) ) | (otherlv_11= 'packages' ( (lv_packages_12_0= rulePackageLayout ) ) ) | ( (lv_layers_13_0= ruleLayer ) ) | ( (lv_connections_14_0= ruleConnection ) ) | ( (lv_sensors_15_0= ruleSensor ) ) | ( (lv_actuators_16_0= ruleActuator ) ) | ( (lv_missions_17_0= ruleMission ) ) | ( (lv_supervisors_18_0= ruleSupervisor ) ) | ( (lv_orders_19_0= ruleOrder ) ) | ( (lv_databases_20_0= ruleDatabase ) ) | ( (lv_processors_21_0= ruleProcessor ) ) | ( (lv_latencyRequirements_22_0= ruleLatencyRequirement ) ) )* otherlv_23= '}' ) ;
    public final EObject ruleArchitecture() throws RecognitionException {
        EObject current = null;

        Token otherlv_1=null;
        Token otherlv_3=null;
        Token otherlv_5=null;
        Token otherlv_7=null;
        Token otherlv_9=null;
        Token otherlv_11=null;
        Token otherlv_23=null;
        AntlrDatatypeRuleToken lv_name_2_0 = null;

        EObject this_Described_4 = null;

        Enumerator lv_category_6_0 = null;

        AntlrDatatypeRuleToken lv_declaredLayers_8_0 = null;

        Enumerator lv_lifecycle_10_0 = null;

        Enumerator lv_packages_12_0 = null;

        EObject lv_layers_13_0 = null;

        EObject lv_connections_14_0 = null;

        EObject lv_sensors_15_0 = null;

        EObject lv_actuators_16_0 = null;

        EObject lv_missions_17_0 = null;

        EObject lv_supervisors_18_0 = null;

        EObject lv_orders_19_0 = null;

        EObject lv_databases_20_0 = null;

        EObject lv_processors_21_0 = null;

        EObject lv_latencyRequirements_22_0 = null;



        	enterRule();

        try {
            // InternalRsamlText.g:78:2: ( ( () otherlv_1= 'architecture' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'category' ( (lv_category_6_0= ruleArchitectureCategory ) ) ) | (otherlv_7= 'declaredLayers' ( (lv_declaredLayers_8_0= ruleInteger ) ) ) | (otherlv_9= 'lifecycle' ( (lv_lifecycle_10_0= ruleNodeLifecycle ) ) ) | (otherlv_11= 'packages' ( (lv_packages_12_0= rulePackageLayout ) ) ) | ( (lv_layers_13_0= ruleLayer ) ) | ( (lv_connections_14_0= ruleConnection ) ) | ( (lv_sensors_15_0= ruleSensor ) ) | ( (lv_actuators_16_0= ruleActuator ) ) | ( (lv_missions_17_0= ruleMission ) ) | ( (lv_supervisors_18_0= ruleSupervisor ) ) | ( (lv_orders_19_0= ruleOrder ) ) | ( (lv_databases_20_0= ruleDatabase ) ) | ( (lv_processors_21_0= ruleProcessor ) ) | ( (lv_latencyRequirements_22_0= ruleLatencyRequirement ) ) )* otherlv_23= '}' ) )
            // InternalRsamlText.g:79:2: ( () otherlv_1= 'architecture' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'category' ( (lv_category_6_0= ruleArchitectureCategory ) ) ) | (otherlv_7= 'declaredLayers' ( (lv_declaredLayers_8_0= ruleInteger ) ) ) | (otherlv_9= 'lifecycle' ( (lv_lifecycle_10_0= ruleNodeLifecycle ) ) ) | (otherlv_11= 'packages' ( (lv_packages_12_0= rulePackageLayout ) ) ) | ( (lv_layers_13_0= ruleLayer ) ) | ( (lv_connections_14_0= ruleConnection ) ) | ( (lv_sensors_15_0= ruleSensor ) ) | ( (lv_actuators_16_0= ruleActuator ) ) | ( (lv_missions_17_0= ruleMission ) ) | ( (lv_supervisors_18_0= ruleSupervisor ) ) | ( (lv_orders_19_0= ruleOrder ) ) | ( (lv_databases_20_0= ruleDatabase ) ) | ( (lv_processors_21_0= ruleProcessor ) ) | ( (lv_latencyRequirements_22_0= ruleLatencyRequirement ) ) )* otherlv_23= '}' )
            {
            // InternalRsamlText.g:79:2: ( () otherlv_1= 'architecture' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'category' ( (lv_category_6_0= ruleArchitectureCategory ) ) ) | (otherlv_7= 'declaredLayers' ( (lv_declaredLayers_8_0= ruleInteger ) ) ) | (otherlv_9= 'lifecycle' ( (lv_lifecycle_10_0= ruleNodeLifecycle ) ) ) | (otherlv_11= 'packages' ( (lv_packages_12_0= rulePackageLayout ) ) ) | ( (lv_layers_13_0= ruleLayer ) ) | ( (lv_connections_14_0= ruleConnection ) ) | ( (lv_sensors_15_0= ruleSensor ) ) | ( (lv_actuators_16_0= ruleActuator ) ) | ( (lv_missions_17_0= ruleMission ) ) | ( (lv_supervisors_18_0= ruleSupervisor ) ) | ( (lv_orders_19_0= ruleOrder ) ) | ( (lv_databases_20_0= ruleDatabase ) ) | ( (lv_processors_21_0= ruleProcessor ) ) | ( (lv_latencyRequirements_22_0= ruleLatencyRequirement ) ) )* otherlv_23= '}' )
            // InternalRsamlText.g:80:3: () otherlv_1= 'architecture' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'category' ( (lv_category_6_0= ruleArchitectureCategory ) ) ) | (otherlv_7= 'declaredLayers' ( (lv_declaredLayers_8_0= ruleInteger ) ) ) | (otherlv_9= 'lifecycle' ( (lv_lifecycle_10_0= ruleNodeLifecycle ) ) ) | (otherlv_11= 'packages' ( (lv_packages_12_0= rulePackageLayout ) ) ) | ( (lv_layers_13_0= ruleLayer ) ) | ( (lv_connections_14_0= ruleConnection ) ) | ( (lv_sensors_15_0= ruleSensor ) ) | ( (lv_actuators_16_0= ruleActuator ) ) | ( (lv_missions_17_0= ruleMission ) ) | ( (lv_supervisors_18_0= ruleSupervisor ) ) | ( (lv_orders_19_0= ruleOrder ) ) | ( (lv_databases_20_0= ruleDatabase ) ) | ( (lv_processors_21_0= ruleProcessor ) ) | ( (lv_latencyRequirements_22_0= ruleLatencyRequirement ) ) )* otherlv_23= '}'
            {
            // InternalRsamlText.g:80:3: ()
            // InternalRsamlText.g:81:4: 
            {

            				current = forceCreateModelElement(
            					grammarAccess.getArchitectureAccess().getArchitectureAction_0(),
            					current);
            			

            }

            otherlv_1=(Token)match(input,11,FOLLOW_3); 

            			newLeafNode(otherlv_1, grammarAccess.getArchitectureAccess().getArchitectureKeyword_1());
            		
            // InternalRsamlText.g:91:3: ( (lv_name_2_0= ruleName ) )?
            int alt1=2;
            int LA1_0 = input.LA(1);

            if ( ((LA1_0>=RULE_STRING && LA1_0<=RULE_ID)||LA1_0==11||(LA1_0>=13 && LA1_0<=16)||(LA1_0>=18 && LA1_0<=29)||(LA1_0>=31 && LA1_0<=44)||(LA1_0>=46 && LA1_0<=80)||(LA1_0>=82 && LA1_0<=118)) ) {
                alt1=1;
            }
            switch (alt1) {
                case 1 :
                    // InternalRsamlText.g:92:4: (lv_name_2_0= ruleName )
                    {
                    // InternalRsamlText.g:92:4: (lv_name_2_0= ruleName )
                    // InternalRsamlText.g:93:5: lv_name_2_0= ruleName
                    {

                    					newCompositeNode(grammarAccess.getArchitectureAccess().getNameNameParserRuleCall_2_0());
                    				
                    pushFollow(FOLLOW_4);
                    lv_name_2_0=ruleName();

                    state._fsp--;


                    					if (current==null) {
                    						current = createModelElementForParent(grammarAccess.getArchitectureRule());
                    					}
                    					set(
                    						current,
                    						"name",
                    						lv_name_2_0,
                    						"org.rsaml.text.RsamlText.Name");
                    					afterParserOrEnumRuleCall();
                    				

                    }


                    }
                    break;

            }

            otherlv_3=(Token)match(input,12,FOLLOW_5); 

            			newLeafNode(otherlv_3, grammarAccess.getArchitectureAccess().getLeftCurlyBracketKeyword_3());
            		
            // InternalRsamlText.g:114:3: (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'category' ( (lv_category_6_0= ruleArchitectureCategory ) ) ) | (otherlv_7= 'declaredLayers' ( (lv_declaredLayers_8_0= ruleInteger ) ) ) | (otherlv_9= 'lifecycle' ( (lv_lifecycle_10_0= ruleNodeLifecycle ) ) ) | (otherlv_11= 'packages' ( (lv_packages_12_0= rulePackageLayout ) ) ) | ( (lv_layers_13_0= ruleLayer ) ) | ( (lv_connections_14_0= ruleConnection ) ) | ( (lv_sensors_15_0= ruleSensor ) ) | ( (lv_actuators_16_0= ruleActuator ) ) | ( (lv_missions_17_0= ruleMission ) ) | ( (lv_supervisors_18_0= ruleSupervisor ) ) | ( (lv_orders_19_0= ruleOrder ) ) | ( (lv_databases_20_0= ruleDatabase ) ) | ( (lv_processors_21_0= ruleProcessor ) ) | ( (lv_latencyRequirements_22_0= ruleLatencyRequirement ) ) )*
            loop2:
            do {
                int alt2=16;
                switch ( input.LA(1) ) {
                case 18:
                    {
                    alt2=1;
                    }
                    break;
                case 13:
                    {
                    alt2=2;
                    }
                    break;
                case 14:
                    {
                    alt2=3;
                    }
                    break;
                case 15:
                    {
                    alt2=4;
                    }
                    break;
                case 16:
                    {
                    alt2=5;
                    }
                    break;
                case 25:
                    {
                    alt2=6;
                    }
                    break;
                case 44:
                    {
                    alt2=7;
                    }
                    break;
                case 51:
                    {
                    alt2=8;
                    }
                    break;
                case 53:
                    {
                    alt2=9;
                    }
                    break;
                case 54:
                    {
                    alt2=10;
                    }
                    break;
                case 61:
                    {
                    alt2=11;
                    }
                    break;
                case 64:
                    {
                    alt2=12;
                    }
                    break;
                case 68:
                    {
                    alt2=13;
                    }
                    break;
                case 71:
                    {
                    alt2=14;
                    }
                    break;
                case 76:
                    {
                    alt2=15;
                    }
                    break;

                }

                switch (alt2) {
            	case 1 :
            	    // InternalRsamlText.g:115:4: this_Described_4= ruleDescribed[$current]
            	    {

            	    				if (current==null) {
            	    					current = createModelElement(grammarAccess.getArchitectureRule());
            	    				}
            	    				newCompositeNode(grammarAccess.getArchitectureAccess().getDescribedParserRuleCall_4_0());
            	    			
            	    pushFollow(FOLLOW_5);
            	    this_Described_4=ruleDescribed(current);

            	    state._fsp--;


            	    				current = this_Described_4;
            	    				afterParserOrEnumRuleCall();
            	    			

            	    }
            	    break;
            	case 2 :
            	    // InternalRsamlText.g:127:4: (otherlv_5= 'category' ( (lv_category_6_0= ruleArchitectureCategory ) ) )
            	    {
            	    // InternalRsamlText.g:127:4: (otherlv_5= 'category' ( (lv_category_6_0= ruleArchitectureCategory ) ) )
            	    // InternalRsamlText.g:128:5: otherlv_5= 'category' ( (lv_category_6_0= ruleArchitectureCategory ) )
            	    {
            	    otherlv_5=(Token)match(input,13,FOLLOW_6); 

            	    					newLeafNode(otherlv_5, grammarAccess.getArchitectureAccess().getCategoryKeyword_4_1_0());
            	    				
            	    // InternalRsamlText.g:132:5: ( (lv_category_6_0= ruleArchitectureCategory ) )
            	    // InternalRsamlText.g:133:6: (lv_category_6_0= ruleArchitectureCategory )
            	    {
            	    // InternalRsamlText.g:133:6: (lv_category_6_0= ruleArchitectureCategory )
            	    // InternalRsamlText.g:134:7: lv_category_6_0= ruleArchitectureCategory
            	    {

            	    							newCompositeNode(grammarAccess.getArchitectureAccess().getCategoryArchitectureCategoryEnumRuleCall_4_1_1_0());
            	    						
            	    pushFollow(FOLLOW_5);
            	    lv_category_6_0=ruleArchitectureCategory();

            	    state._fsp--;


            	    							if (current==null) {
            	    								current = createModelElementForParent(grammarAccess.getArchitectureRule());
            	    							}
            	    							set(
            	    								current,
            	    								"category",
            	    								lv_category_6_0,
            	    								"org.rsaml.text.RsamlText.ArchitectureCategory");
            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;
            	case 3 :
            	    // InternalRsamlText.g:153:4: (otherlv_7= 'declaredLayers' ( (lv_declaredLayers_8_0= ruleInteger ) ) )
            	    {
            	    // InternalRsamlText.g:153:4: (otherlv_7= 'declaredLayers' ( (lv_declaredLayers_8_0= ruleInteger ) ) )
            	    // InternalRsamlText.g:154:5: otherlv_7= 'declaredLayers' ( (lv_declaredLayers_8_0= ruleInteger ) )
            	    {
            	    otherlv_7=(Token)match(input,14,FOLLOW_7); 

            	    					newLeafNode(otherlv_7, grammarAccess.getArchitectureAccess().getDeclaredLayersKeyword_4_2_0());
            	    				
            	    // InternalRsamlText.g:158:5: ( (lv_declaredLayers_8_0= ruleInteger ) )
            	    // InternalRsamlText.g:159:6: (lv_declaredLayers_8_0= ruleInteger )
            	    {
            	    // InternalRsamlText.g:159:6: (lv_declaredLayers_8_0= ruleInteger )
            	    // InternalRsamlText.g:160:7: lv_declaredLayers_8_0= ruleInteger
            	    {

            	    							newCompositeNode(grammarAccess.getArchitectureAccess().getDeclaredLayersIntegerParserRuleCall_4_2_1_0());
            	    						
            	    pushFollow(FOLLOW_5);
            	    lv_declaredLayers_8_0=ruleInteger();

            	    state._fsp--;


            	    							if (current==null) {
            	    								current = createModelElementForParent(grammarAccess.getArchitectureRule());
            	    							}
            	    							set(
            	    								current,
            	    								"declaredLayers",
            	    								lv_declaredLayers_8_0,
            	    								"org.rsaml.text.RsamlText.Integer");
            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;
            	case 4 :
            	    // InternalRsamlText.g:179:4: (otherlv_9= 'lifecycle' ( (lv_lifecycle_10_0= ruleNodeLifecycle ) ) )
            	    {
            	    // InternalRsamlText.g:179:4: (otherlv_9= 'lifecycle' ( (lv_lifecycle_10_0= ruleNodeLifecycle ) ) )
            	    // InternalRsamlText.g:180:5: otherlv_9= 'lifecycle' ( (lv_lifecycle_10_0= ruleNodeLifecycle ) )
            	    {
            	    otherlv_9=(Token)match(input,15,FOLLOW_8); 

            	    					newLeafNode(otherlv_9, grammarAccess.getArchitectureAccess().getLifecycleKeyword_4_3_0());
            	    				
            	    // InternalRsamlText.g:184:5: ( (lv_lifecycle_10_0= ruleNodeLifecycle ) )
            	    // InternalRsamlText.g:185:6: (lv_lifecycle_10_0= ruleNodeLifecycle )
            	    {
            	    // InternalRsamlText.g:185:6: (lv_lifecycle_10_0= ruleNodeLifecycle )
            	    // InternalRsamlText.g:186:7: lv_lifecycle_10_0= ruleNodeLifecycle
            	    {

            	    							newCompositeNode(grammarAccess.getArchitectureAccess().getLifecycleNodeLifecycleEnumRuleCall_4_3_1_0());
            	    						
            	    pushFollow(FOLLOW_5);
            	    lv_lifecycle_10_0=ruleNodeLifecycle();

            	    state._fsp--;


            	    							if (current==null) {
            	    								current = createModelElementForParent(grammarAccess.getArchitectureRule());
            	    							}
            	    							set(
            	    								current,
            	    								"lifecycle",
            	    								lv_lifecycle_10_0,
            	    								"org.rsaml.text.RsamlText.NodeLifecycle");
            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;
            	case 5 :
            	    // InternalRsamlText.g:205:4: (otherlv_11= 'packages' ( (lv_packages_12_0= rulePackageLayout ) ) )
            	    {
            	    // InternalRsamlText.g:205:4: (otherlv_11= 'packages' ( (lv_packages_12_0= rulePackageLayout ) ) )
            	    // InternalRsamlText.g:206:5: otherlv_11= 'packages' ( (lv_packages_12_0= rulePackageLayout ) )
            	    {
            	    otherlv_11=(Token)match(input,16,FOLLOW_9); 

            	    					newLeafNode(otherlv_11, grammarAccess.getArchitectureAccess().getPackagesKeyword_4_4_0());
            	    				
            	    // InternalRsamlText.g:210:5: ( (lv_packages_12_0= rulePackageLayout ) )
            	    // InternalRsamlText.g:211:6: (lv_packages_12_0= rulePackageLayout )
            	    {
            	    // InternalRsamlText.g:211:6: (lv_packages_12_0= rulePackageLayout )
            	    // InternalRsamlText.g:212:7: lv_packages_12_0= rulePackageLayout
            	    {

            	    							newCompositeNode(grammarAccess.getArchitectureAccess().getPackagesPackageLayoutEnumRuleCall_4_4_1_0());
            	    						
            	    pushFollow(FOLLOW_5);
            	    lv_packages_12_0=rulePackageLayout();

            	    state._fsp--;


            	    							if (current==null) {
            	    								current = createModelElementForParent(grammarAccess.getArchitectureRule());
            	    							}
            	    							set(
            	    								current,
            	    								"packages",
            	    								lv_packages_12_0,
            	    								"org.rsaml.text.RsamlText.PackageLayout");
            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;
            	case 6 :
            	    // InternalRsamlText.g:231:4: ( (lv_layers_13_0= ruleLayer ) )
            	    {
            	    // InternalRsamlText.g:231:4: ( (lv_layers_13_0= ruleLayer ) )
            	    // InternalRsamlText.g:232:5: (lv_layers_13_0= ruleLayer )
            	    {
            	    // InternalRsamlText.g:232:5: (lv_layers_13_0= ruleLayer )
            	    // InternalRsamlText.g:233:6: lv_layers_13_0= ruleLayer
            	    {

            	    						newCompositeNode(grammarAccess.getArchitectureAccess().getLayersLayerParserRuleCall_4_5_0());
            	    					
            	    pushFollow(FOLLOW_5);
            	    lv_layers_13_0=ruleLayer();

            	    state._fsp--;


            	    						if (current==null) {
            	    							current = createModelElementForParent(grammarAccess.getArchitectureRule());
            	    						}
            	    						add(
            	    							current,
            	    							"layers",
            	    							lv_layers_13_0,
            	    							"org.rsaml.text.RsamlText.Layer");
            	    						afterParserOrEnumRuleCall();
            	    					

            	    }


            	    }


            	    }
            	    break;
            	case 7 :
            	    // InternalRsamlText.g:251:4: ( (lv_connections_14_0= ruleConnection ) )
            	    {
            	    // InternalRsamlText.g:251:4: ( (lv_connections_14_0= ruleConnection ) )
            	    // InternalRsamlText.g:252:5: (lv_connections_14_0= ruleConnection )
            	    {
            	    // InternalRsamlText.g:252:5: (lv_connections_14_0= ruleConnection )
            	    // InternalRsamlText.g:253:6: lv_connections_14_0= ruleConnection
            	    {

            	    						newCompositeNode(grammarAccess.getArchitectureAccess().getConnectionsConnectionParserRuleCall_4_6_0());
            	    					
            	    pushFollow(FOLLOW_5);
            	    lv_connections_14_0=ruleConnection();

            	    state._fsp--;


            	    						if (current==null) {
            	    							current = createModelElementForParent(grammarAccess.getArchitectureRule());
            	    						}
            	    						add(
            	    							current,
            	    							"connections",
            	    							lv_connections_14_0,
            	    							"org.rsaml.text.RsamlText.Connection");
            	    						afterParserOrEnumRuleCall();
            	    					

            	    }


            	    }


            	    }
            	    break;
            	case 8 :
            	    // InternalRsamlText.g:271:4: ( (lv_sensors_15_0= ruleSensor ) )
            	    {
            	    // InternalRsamlText.g:271:4: ( (lv_sensors_15_0= ruleSensor ) )
            	    // InternalRsamlText.g:272:5: (lv_sensors_15_0= ruleSensor )
            	    {
            	    // InternalRsamlText.g:272:5: (lv_sensors_15_0= ruleSensor )
            	    // InternalRsamlText.g:273:6: lv_sensors_15_0= ruleSensor
            	    {

            	    						newCompositeNode(grammarAccess.getArchitectureAccess().getSensorsSensorParserRuleCall_4_7_0());
            	    					
            	    pushFollow(FOLLOW_5);
            	    lv_sensors_15_0=ruleSensor();

            	    state._fsp--;


            	    						if (current==null) {
            	    							current = createModelElementForParent(grammarAccess.getArchitectureRule());
            	    						}
            	    						add(
            	    							current,
            	    							"sensors",
            	    							lv_sensors_15_0,
            	    							"org.rsaml.text.RsamlText.Sensor");
            	    						afterParserOrEnumRuleCall();
            	    					

            	    }


            	    }


            	    }
            	    break;
            	case 9 :
            	    // InternalRsamlText.g:291:4: ( (lv_actuators_16_0= ruleActuator ) )
            	    {
            	    // InternalRsamlText.g:291:4: ( (lv_actuators_16_0= ruleActuator ) )
            	    // InternalRsamlText.g:292:5: (lv_actuators_16_0= ruleActuator )
            	    {
            	    // InternalRsamlText.g:292:5: (lv_actuators_16_0= ruleActuator )
            	    // InternalRsamlText.g:293:6: lv_actuators_16_0= ruleActuator
            	    {

            	    						newCompositeNode(grammarAccess.getArchitectureAccess().getActuatorsActuatorParserRuleCall_4_8_0());
            	    					
            	    pushFollow(FOLLOW_5);
            	    lv_actuators_16_0=ruleActuator();

            	    state._fsp--;


            	    						if (current==null) {
            	    							current = createModelElementForParent(grammarAccess.getArchitectureRule());
            	    						}
            	    						add(
            	    							current,
            	    							"actuators",
            	    							lv_actuators_16_0,
            	    							"org.rsaml.text.RsamlText.Actuator");
            	    						afterParserOrEnumRuleCall();
            	    					

            	    }


            	    }


            	    }
            	    break;
            	case 10 :
            	    // InternalRsamlText.g:311:4: ( (lv_missions_17_0= ruleMission ) )
            	    {
            	    // InternalRsamlText.g:311:4: ( (lv_missions_17_0= ruleMission ) )
            	    // InternalRsamlText.g:312:5: (lv_missions_17_0= ruleMission )
            	    {
            	    // InternalRsamlText.g:312:5: (lv_missions_17_0= ruleMission )
            	    // InternalRsamlText.g:313:6: lv_missions_17_0= ruleMission
            	    {

            	    						newCompositeNode(grammarAccess.getArchitectureAccess().getMissionsMissionParserRuleCall_4_9_0());
            	    					
            	    pushFollow(FOLLOW_5);
            	    lv_missions_17_0=ruleMission();

            	    state._fsp--;


            	    						if (current==null) {
            	    							current = createModelElementForParent(grammarAccess.getArchitectureRule());
            	    						}
            	    						add(
            	    							current,
            	    							"missions",
            	    							lv_missions_17_0,
            	    							"org.rsaml.text.RsamlText.Mission");
            	    						afterParserOrEnumRuleCall();
            	    					

            	    }


            	    }


            	    }
            	    break;
            	case 11 :
            	    // InternalRsamlText.g:331:4: ( (lv_supervisors_18_0= ruleSupervisor ) )
            	    {
            	    // InternalRsamlText.g:331:4: ( (lv_supervisors_18_0= ruleSupervisor ) )
            	    // InternalRsamlText.g:332:5: (lv_supervisors_18_0= ruleSupervisor )
            	    {
            	    // InternalRsamlText.g:332:5: (lv_supervisors_18_0= ruleSupervisor )
            	    // InternalRsamlText.g:333:6: lv_supervisors_18_0= ruleSupervisor
            	    {

            	    						newCompositeNode(grammarAccess.getArchitectureAccess().getSupervisorsSupervisorParserRuleCall_4_10_0());
            	    					
            	    pushFollow(FOLLOW_5);
            	    lv_supervisors_18_0=ruleSupervisor();

            	    state._fsp--;


            	    						if (current==null) {
            	    							current = createModelElementForParent(grammarAccess.getArchitectureRule());
            	    						}
            	    						add(
            	    							current,
            	    							"supervisors",
            	    							lv_supervisors_18_0,
            	    							"org.rsaml.text.RsamlText.Supervisor");
            	    						afterParserOrEnumRuleCall();
            	    					

            	    }


            	    }


            	    }
            	    break;
            	case 12 :
            	    // InternalRsamlText.g:351:4: ( (lv_orders_19_0= ruleOrder ) )
            	    {
            	    // InternalRsamlText.g:351:4: ( (lv_orders_19_0= ruleOrder ) )
            	    // InternalRsamlText.g:352:5: (lv_orders_19_0= ruleOrder )
            	    {
            	    // InternalRsamlText.g:352:5: (lv_orders_19_0= ruleOrder )
            	    // InternalRsamlText.g:353:6: lv_orders_19_0= ruleOrder
            	    {

            	    						newCompositeNode(grammarAccess.getArchitectureAccess().getOrdersOrderParserRuleCall_4_11_0());
            	    					
            	    pushFollow(FOLLOW_5);
            	    lv_orders_19_0=ruleOrder();

            	    state._fsp--;


            	    						if (current==null) {
            	    							current = createModelElementForParent(grammarAccess.getArchitectureRule());
            	    						}
            	    						add(
            	    							current,
            	    							"orders",
            	    							lv_orders_19_0,
            	    							"org.rsaml.text.RsamlText.Order");
            	    						afterParserOrEnumRuleCall();
            	    					

            	    }


            	    }


            	    }
            	    break;
            	case 13 :
            	    // InternalRsamlText.g:371:4: ( (lv_databases_20_0= ruleDatabase ) )
            	    {
            	    // InternalRsamlText.g:371:4: ( (lv_databases_20_0= ruleDatabase ) )
            	    // InternalRsamlText.g:372:5: (lv_databases_20_0= ruleDatabase )
            	    {
            	    // InternalRsamlText.g:372:5: (lv_databases_20_0= ruleDatabase )
            	    // InternalRsamlText.g:373:6: lv_databases_20_0= ruleDatabase
            	    {

            	    						newCompositeNode(grammarAccess.getArchitectureAccess().getDatabasesDatabaseParserRuleCall_4_12_0());
            	    					
            	    pushFollow(FOLLOW_5);
            	    lv_databases_20_0=ruleDatabase();

            	    state._fsp--;


            	    						if (current==null) {
            	    							current = createModelElementForParent(grammarAccess.getArchitectureRule());
            	    						}
            	    						add(
            	    							current,
            	    							"databases",
            	    							lv_databases_20_0,
            	    							"org.rsaml.text.RsamlText.Database");
            	    						afterParserOrEnumRuleCall();
            	    					

            	    }


            	    }


            	    }
            	    break;
            	case 14 :
            	    // InternalRsamlText.g:391:4: ( (lv_processors_21_0= ruleProcessor ) )
            	    {
            	    // InternalRsamlText.g:391:4: ( (lv_processors_21_0= ruleProcessor ) )
            	    // InternalRsamlText.g:392:5: (lv_processors_21_0= ruleProcessor )
            	    {
            	    // InternalRsamlText.g:392:5: (lv_processors_21_0= ruleProcessor )
            	    // InternalRsamlText.g:393:6: lv_processors_21_0= ruleProcessor
            	    {

            	    						newCompositeNode(grammarAccess.getArchitectureAccess().getProcessorsProcessorParserRuleCall_4_13_0());
            	    					
            	    pushFollow(FOLLOW_5);
            	    lv_processors_21_0=ruleProcessor();

            	    state._fsp--;


            	    						if (current==null) {
            	    							current = createModelElementForParent(grammarAccess.getArchitectureRule());
            	    						}
            	    						add(
            	    							current,
            	    							"processors",
            	    							lv_processors_21_0,
            	    							"org.rsaml.text.RsamlText.Processor");
            	    						afterParserOrEnumRuleCall();
            	    					

            	    }


            	    }


            	    }
            	    break;
            	case 15 :
            	    // InternalRsamlText.g:411:4: ( (lv_latencyRequirements_22_0= ruleLatencyRequirement ) )
            	    {
            	    // InternalRsamlText.g:411:4: ( (lv_latencyRequirements_22_0= ruleLatencyRequirement ) )
            	    // InternalRsamlText.g:412:5: (lv_latencyRequirements_22_0= ruleLatencyRequirement )
            	    {
            	    // InternalRsamlText.g:412:5: (lv_latencyRequirements_22_0= ruleLatencyRequirement )
            	    // InternalRsamlText.g:413:6: lv_latencyRequirements_22_0= ruleLatencyRequirement
            	    {

            	    						newCompositeNode(grammarAccess.getArchitectureAccess().getLatencyRequirementsLatencyRequirementParserRuleCall_4_14_0());
            	    					
            	    pushFollow(FOLLOW_5);
            	    lv_latencyRequirements_22_0=ruleLatencyRequirement();

            	    state._fsp--;


            	    						if (current==null) {
            	    							current = createModelElementForParent(grammarAccess.getArchitectureRule());
            	    						}
            	    						add(
            	    							current,
            	    							"latencyRequirements",
            	    							lv_latencyRequirements_22_0,
            	    							"org.rsaml.text.RsamlText.LatencyRequirement");
            	    						afterParserOrEnumRuleCall();
            	    					

            	    }


            	    }


            	    }
            	    break;

            	default :
            	    break loop2;
                }
            } while (true);

            otherlv_23=(Token)match(input,17,FOLLOW_2); 

            			newLeafNode(otherlv_23, grammarAccess.getArchitectureAccess().getRightCurlyBracketKeyword_5());
            		

            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "ruleArchitecture"


    // $ANTLR start "ruleDescribed"
    // InternalRsamlText.g:440:1: ruleDescribed[EObject in_current] returns [EObject current=in_current] : (otherlv_0= 'description' ( (lv_description_1_0= RULE_STRING ) ) ) ;
    public final EObject ruleDescribed(EObject in_current) throws RecognitionException {
        EObject current = in_current;

        Token otherlv_0=null;
        Token lv_description_1_0=null;


        	enterRule();

        try {
            // InternalRsamlText.g:446:2: ( (otherlv_0= 'description' ( (lv_description_1_0= RULE_STRING ) ) ) )
            // InternalRsamlText.g:447:2: (otherlv_0= 'description' ( (lv_description_1_0= RULE_STRING ) ) )
            {
            // InternalRsamlText.g:447:2: (otherlv_0= 'description' ( (lv_description_1_0= RULE_STRING ) ) )
            // InternalRsamlText.g:448:3: otherlv_0= 'description' ( (lv_description_1_0= RULE_STRING ) )
            {
            otherlv_0=(Token)match(input,18,FOLLOW_10); 

            			newLeafNode(otherlv_0, grammarAccess.getDescribedAccess().getDescriptionKeyword_0());
            		
            // InternalRsamlText.g:452:3: ( (lv_description_1_0= RULE_STRING ) )
            // InternalRsamlText.g:453:4: (lv_description_1_0= RULE_STRING )
            {
            // InternalRsamlText.g:453:4: (lv_description_1_0= RULE_STRING )
            // InternalRsamlText.g:454:5: lv_description_1_0= RULE_STRING
            {
            lv_description_1_0=(Token)match(input,RULE_STRING,FOLLOW_2); 

            					newLeafNode(lv_description_1_0, grammarAccess.getDescribedAccess().getDescriptionSTRINGTerminalRuleCall_1_0());
            				

            					if (current==null) {
            						current = createModelElement(grammarAccess.getDescribedRule());
            					}
            					setWithLastConsumed(
            						current,
            						"description",
            						lv_description_1_0,
            						"org.rsaml.text.RsamlText.STRING");
            				

            }


            }


            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "ruleDescribed"


    // $ANTLR start "ruleUnit"
    // InternalRsamlText.g:475:1: ruleUnit[EObject in_current] returns [EObject current=in_current] : (otherlv_0= 'unit' ( (lv_timeUnit_1_0= ruleTimeUnit ) ) ) ;
    public final EObject ruleUnit(EObject in_current) throws RecognitionException {
        EObject current = in_current;

        Token otherlv_0=null;
        Enumerator lv_timeUnit_1_0 = null;



        	enterRule();

        try {
            // InternalRsamlText.g:481:2: ( (otherlv_0= 'unit' ( (lv_timeUnit_1_0= ruleTimeUnit ) ) ) )
            // InternalRsamlText.g:482:2: (otherlv_0= 'unit' ( (lv_timeUnit_1_0= ruleTimeUnit ) ) )
            {
            // InternalRsamlText.g:482:2: (otherlv_0= 'unit' ( (lv_timeUnit_1_0= ruleTimeUnit ) ) )
            // InternalRsamlText.g:483:3: otherlv_0= 'unit' ( (lv_timeUnit_1_0= ruleTimeUnit ) )
            {
            otherlv_0=(Token)match(input,19,FOLLOW_11); 

            			newLeafNode(otherlv_0, grammarAccess.getUnitAccess().getUnitKeyword_0());
            		
            // InternalRsamlText.g:487:3: ( (lv_timeUnit_1_0= ruleTimeUnit ) )
            // InternalRsamlText.g:488:4: (lv_timeUnit_1_0= ruleTimeUnit )
            {
            // InternalRsamlText.g:488:4: (lv_timeUnit_1_0= ruleTimeUnit )
            // InternalRsamlText.g:489:5: lv_timeUnit_1_0= ruleTimeUnit
            {

            					newCompositeNode(grammarAccess.getUnitAccess().getTimeUnitTimeUnitEnumRuleCall_1_0());
            				
            pushFollow(FOLLOW_2);
            lv_timeUnit_1_0=ruleTimeUnit();

            state._fsp--;


            					if (current==null) {
            						current = createModelElementForParent(grammarAccess.getUnitRule());
            					}
            					set(
            						current,
            						"timeUnit",
            						lv_timeUnit_1_0,
            						"org.rsaml.text.RsamlText.TimeUnit");
            					afterParserOrEnumRuleCall();
            				

            }


            }


            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "ruleUnit"


    // $ANTLR start "ruleRealTime"
    // InternalRsamlText.g:511:1: ruleRealTime[EObject in_current] returns [EObject current=in_current] : ( (otherlv_0= 'type' ( (lv_type_1_0= ruleElementType ) ) ) | (otherlv_2= 'execType' ( (lv_execType_3_0= ruleExecutionType ) ) ) | (otherlv_4= 'period' ( (lv_period_5_0= ruleReal ) ) ( (lv_timeUnit_6_0= ruleTimeUnit ) ) ) | (otherlv_7= 'deadline' ( (lv_delay_8_0= ruleReal ) ) ( (lv_timeUnit_9_0= ruleTimeUnit ) ) ) | (otherlv_10= 'wcet' ( (lv_execDuration_11_0= ruleReal ) ) ( (lv_timeUnit_12_0= ruleTimeUnit ) ) ) | this_Unit_13= ruleUnit[$current] ) ;
    public final EObject ruleRealTime(EObject in_current) throws RecognitionException {
        EObject current = in_current;

        Token otherlv_0=null;
        Token otherlv_2=null;
        Token otherlv_4=null;
        Token otherlv_7=null;
        Token otherlv_10=null;
        Enumerator lv_type_1_0 = null;

        Enumerator lv_execType_3_0 = null;

        AntlrDatatypeRuleToken lv_period_5_0 = null;

        Enumerator lv_timeUnit_6_0 = null;

        AntlrDatatypeRuleToken lv_delay_8_0 = null;

        Enumerator lv_timeUnit_9_0 = null;

        AntlrDatatypeRuleToken lv_execDuration_11_0 = null;

        Enumerator lv_timeUnit_12_0 = null;

        EObject this_Unit_13 = null;



        	enterRule();

        try {
            // InternalRsamlText.g:517:2: ( ( (otherlv_0= 'type' ( (lv_type_1_0= ruleElementType ) ) ) | (otherlv_2= 'execType' ( (lv_execType_3_0= ruleExecutionType ) ) ) | (otherlv_4= 'period' ( (lv_period_5_0= ruleReal ) ) ( (lv_timeUnit_6_0= ruleTimeUnit ) ) ) | (otherlv_7= 'deadline' ( (lv_delay_8_0= ruleReal ) ) ( (lv_timeUnit_9_0= ruleTimeUnit ) ) ) | (otherlv_10= 'wcet' ( (lv_execDuration_11_0= ruleReal ) ) ( (lv_timeUnit_12_0= ruleTimeUnit ) ) ) | this_Unit_13= ruleUnit[$current] ) )
            // InternalRsamlText.g:518:2: ( (otherlv_0= 'type' ( (lv_type_1_0= ruleElementType ) ) ) | (otherlv_2= 'execType' ( (lv_execType_3_0= ruleExecutionType ) ) ) | (otherlv_4= 'period' ( (lv_period_5_0= ruleReal ) ) ( (lv_timeUnit_6_0= ruleTimeUnit ) ) ) | (otherlv_7= 'deadline' ( (lv_delay_8_0= ruleReal ) ) ( (lv_timeUnit_9_0= ruleTimeUnit ) ) ) | (otherlv_10= 'wcet' ( (lv_execDuration_11_0= ruleReal ) ) ( (lv_timeUnit_12_0= ruleTimeUnit ) ) ) | this_Unit_13= ruleUnit[$current] )
            {
            // InternalRsamlText.g:518:2: ( (otherlv_0= 'type' ( (lv_type_1_0= ruleElementType ) ) ) | (otherlv_2= 'execType' ( (lv_execType_3_0= ruleExecutionType ) ) ) | (otherlv_4= 'period' ( (lv_period_5_0= ruleReal ) ) ( (lv_timeUnit_6_0= ruleTimeUnit ) ) ) | (otherlv_7= 'deadline' ( (lv_delay_8_0= ruleReal ) ) ( (lv_timeUnit_9_0= ruleTimeUnit ) ) ) | (otherlv_10= 'wcet' ( (lv_execDuration_11_0= ruleReal ) ) ( (lv_timeUnit_12_0= ruleTimeUnit ) ) ) | this_Unit_13= ruleUnit[$current] )
            int alt3=6;
            switch ( input.LA(1) ) {
            case 20:
                {
                alt3=1;
                }
                break;
            case 21:
                {
                alt3=2;
                }
                break;
            case 22:
                {
                alt3=3;
                }
                break;
            case 23:
                {
                alt3=4;
                }
                break;
            case 24:
                {
                alt3=5;
                }
                break;
            case 19:
                {
                alt3=6;
                }
                break;
            default:
                NoViableAltException nvae =
                    new NoViableAltException("", 3, 0, input);

                throw nvae;
            }

            switch (alt3) {
                case 1 :
                    // InternalRsamlText.g:519:3: (otherlv_0= 'type' ( (lv_type_1_0= ruleElementType ) ) )
                    {
                    // InternalRsamlText.g:519:3: (otherlv_0= 'type' ( (lv_type_1_0= ruleElementType ) ) )
                    // InternalRsamlText.g:520:4: otherlv_0= 'type' ( (lv_type_1_0= ruleElementType ) )
                    {
                    otherlv_0=(Token)match(input,20,FOLLOW_12); 

                    				newLeafNode(otherlv_0, grammarAccess.getRealTimeAccess().getTypeKeyword_0_0());
                    			
                    // InternalRsamlText.g:524:4: ( (lv_type_1_0= ruleElementType ) )
                    // InternalRsamlText.g:525:5: (lv_type_1_0= ruleElementType )
                    {
                    // InternalRsamlText.g:525:5: (lv_type_1_0= ruleElementType )
                    // InternalRsamlText.g:526:6: lv_type_1_0= ruleElementType
                    {

                    						newCompositeNode(grammarAccess.getRealTimeAccess().getTypeElementTypeEnumRuleCall_0_1_0());
                    					
                    pushFollow(FOLLOW_2);
                    lv_type_1_0=ruleElementType();

                    state._fsp--;


                    						if (current==null) {
                    							current = createModelElementForParent(grammarAccess.getRealTimeRule());
                    						}
                    						set(
                    							current,
                    							"type",
                    							lv_type_1_0,
                    							"org.rsaml.text.RsamlText.ElementType");
                    						afterParserOrEnumRuleCall();
                    					

                    }


                    }


                    }


                    }
                    break;
                case 2 :
                    // InternalRsamlText.g:545:3: (otherlv_2= 'execType' ( (lv_execType_3_0= ruleExecutionType ) ) )
                    {
                    // InternalRsamlText.g:545:3: (otherlv_2= 'execType' ( (lv_execType_3_0= ruleExecutionType ) ) )
                    // InternalRsamlText.g:546:4: otherlv_2= 'execType' ( (lv_execType_3_0= ruleExecutionType ) )
                    {
                    otherlv_2=(Token)match(input,21,FOLLOW_13); 

                    				newLeafNode(otherlv_2, grammarAccess.getRealTimeAccess().getExecTypeKeyword_1_0());
                    			
                    // InternalRsamlText.g:550:4: ( (lv_execType_3_0= ruleExecutionType ) )
                    // InternalRsamlText.g:551:5: (lv_execType_3_0= ruleExecutionType )
                    {
                    // InternalRsamlText.g:551:5: (lv_execType_3_0= ruleExecutionType )
                    // InternalRsamlText.g:552:6: lv_execType_3_0= ruleExecutionType
                    {

                    						newCompositeNode(grammarAccess.getRealTimeAccess().getExecTypeExecutionTypeEnumRuleCall_1_1_0());
                    					
                    pushFollow(FOLLOW_2);
                    lv_execType_3_0=ruleExecutionType();

                    state._fsp--;


                    						if (current==null) {
                    							current = createModelElementForParent(grammarAccess.getRealTimeRule());
                    						}
                    						set(
                    							current,
                    							"execType",
                    							lv_execType_3_0,
                    							"org.rsaml.text.RsamlText.ExecutionType");
                    						afterParserOrEnumRuleCall();
                    					

                    }


                    }


                    }


                    }
                    break;
                case 3 :
                    // InternalRsamlText.g:571:3: (otherlv_4= 'period' ( (lv_period_5_0= ruleReal ) ) ( (lv_timeUnit_6_0= ruleTimeUnit ) ) )
                    {
                    // InternalRsamlText.g:571:3: (otherlv_4= 'period' ( (lv_period_5_0= ruleReal ) ) ( (lv_timeUnit_6_0= ruleTimeUnit ) ) )
                    // InternalRsamlText.g:572:4: otherlv_4= 'period' ( (lv_period_5_0= ruleReal ) ) ( (lv_timeUnit_6_0= ruleTimeUnit ) )
                    {
                    otherlv_4=(Token)match(input,22,FOLLOW_14); 

                    				newLeafNode(otherlv_4, grammarAccess.getRealTimeAccess().getPeriodKeyword_2_0());
                    			
                    // InternalRsamlText.g:576:4: ( (lv_period_5_0= ruleReal ) )
                    // InternalRsamlText.g:577:5: (lv_period_5_0= ruleReal )
                    {
                    // InternalRsamlText.g:577:5: (lv_period_5_0= ruleReal )
                    // InternalRsamlText.g:578:6: lv_period_5_0= ruleReal
                    {

                    						newCompositeNode(grammarAccess.getRealTimeAccess().getPeriodRealParserRuleCall_2_1_0());
                    					
                    pushFollow(FOLLOW_11);
                    lv_period_5_0=ruleReal();

                    state._fsp--;


                    						if (current==null) {
                    							current = createModelElementForParent(grammarAccess.getRealTimeRule());
                    						}
                    						set(
                    							current,
                    							"period",
                    							lv_period_5_0,
                    							"org.rsaml.text.RsamlText.Real");
                    						afterParserOrEnumRuleCall();
                    					

                    }


                    }

                    // InternalRsamlText.g:595:4: ( (lv_timeUnit_6_0= ruleTimeUnit ) )
                    // InternalRsamlText.g:596:5: (lv_timeUnit_6_0= ruleTimeUnit )
                    {
                    // InternalRsamlText.g:596:5: (lv_timeUnit_6_0= ruleTimeUnit )
                    // InternalRsamlText.g:597:6: lv_timeUnit_6_0= ruleTimeUnit
                    {

                    						newCompositeNode(grammarAccess.getRealTimeAccess().getTimeUnitTimeUnitEnumRuleCall_2_2_0());
                    					
                    pushFollow(FOLLOW_2);
                    lv_timeUnit_6_0=ruleTimeUnit();

                    state._fsp--;


                    						if (current==null) {
                    							current = createModelElementForParent(grammarAccess.getRealTimeRule());
                    						}
                    						set(
                    							current,
                    							"timeUnit",
                    							lv_timeUnit_6_0,
                    							"org.rsaml.text.RsamlText.TimeUnit");
                    						afterParserOrEnumRuleCall();
                    					

                    }


                    }


                    }


                    }
                    break;
                case 4 :
                    // InternalRsamlText.g:616:3: (otherlv_7= 'deadline' ( (lv_delay_8_0= ruleReal ) ) ( (lv_timeUnit_9_0= ruleTimeUnit ) ) )
                    {
                    // InternalRsamlText.g:616:3: (otherlv_7= 'deadline' ( (lv_delay_8_0= ruleReal ) ) ( (lv_timeUnit_9_0= ruleTimeUnit ) ) )
                    // InternalRsamlText.g:617:4: otherlv_7= 'deadline' ( (lv_delay_8_0= ruleReal ) ) ( (lv_timeUnit_9_0= ruleTimeUnit ) )
                    {
                    otherlv_7=(Token)match(input,23,FOLLOW_14); 

                    				newLeafNode(otherlv_7, grammarAccess.getRealTimeAccess().getDeadlineKeyword_3_0());
                    			
                    // InternalRsamlText.g:621:4: ( (lv_delay_8_0= ruleReal ) )
                    // InternalRsamlText.g:622:5: (lv_delay_8_0= ruleReal )
                    {
                    // InternalRsamlText.g:622:5: (lv_delay_8_0= ruleReal )
                    // InternalRsamlText.g:623:6: lv_delay_8_0= ruleReal
                    {

                    						newCompositeNode(grammarAccess.getRealTimeAccess().getDelayRealParserRuleCall_3_1_0());
                    					
                    pushFollow(FOLLOW_11);
                    lv_delay_8_0=ruleReal();

                    state._fsp--;


                    						if (current==null) {
                    							current = createModelElementForParent(grammarAccess.getRealTimeRule());
                    						}
                    						set(
                    							current,
                    							"delay",
                    							lv_delay_8_0,
                    							"org.rsaml.text.RsamlText.Real");
                    						afterParserOrEnumRuleCall();
                    					

                    }


                    }

                    // InternalRsamlText.g:640:4: ( (lv_timeUnit_9_0= ruleTimeUnit ) )
                    // InternalRsamlText.g:641:5: (lv_timeUnit_9_0= ruleTimeUnit )
                    {
                    // InternalRsamlText.g:641:5: (lv_timeUnit_9_0= ruleTimeUnit )
                    // InternalRsamlText.g:642:6: lv_timeUnit_9_0= ruleTimeUnit
                    {

                    						newCompositeNode(grammarAccess.getRealTimeAccess().getTimeUnitTimeUnitEnumRuleCall_3_2_0());
                    					
                    pushFollow(FOLLOW_2);
                    lv_timeUnit_9_0=ruleTimeUnit();

                    state._fsp--;


                    						if (current==null) {
                    							current = createModelElementForParent(grammarAccess.getRealTimeRule());
                    						}
                    						set(
                    							current,
                    							"timeUnit",
                    							lv_timeUnit_9_0,
                    							"org.rsaml.text.RsamlText.TimeUnit");
                    						afterParserOrEnumRuleCall();
                    					

                    }


                    }


                    }


                    }
                    break;
                case 5 :
                    // InternalRsamlText.g:661:3: (otherlv_10= 'wcet' ( (lv_execDuration_11_0= ruleReal ) ) ( (lv_timeUnit_12_0= ruleTimeUnit ) ) )
                    {
                    // InternalRsamlText.g:661:3: (otherlv_10= 'wcet' ( (lv_execDuration_11_0= ruleReal ) ) ( (lv_timeUnit_12_0= ruleTimeUnit ) ) )
                    // InternalRsamlText.g:662:4: otherlv_10= 'wcet' ( (lv_execDuration_11_0= ruleReal ) ) ( (lv_timeUnit_12_0= ruleTimeUnit ) )
                    {
                    otherlv_10=(Token)match(input,24,FOLLOW_14); 

                    				newLeafNode(otherlv_10, grammarAccess.getRealTimeAccess().getWcetKeyword_4_0());
                    			
                    // InternalRsamlText.g:666:4: ( (lv_execDuration_11_0= ruleReal ) )
                    // InternalRsamlText.g:667:5: (lv_execDuration_11_0= ruleReal )
                    {
                    // InternalRsamlText.g:667:5: (lv_execDuration_11_0= ruleReal )
                    // InternalRsamlText.g:668:6: lv_execDuration_11_0= ruleReal
                    {

                    						newCompositeNode(grammarAccess.getRealTimeAccess().getExecDurationRealParserRuleCall_4_1_0());
                    					
                    pushFollow(FOLLOW_11);
                    lv_execDuration_11_0=ruleReal();

                    state._fsp--;


                    						if (current==null) {
                    							current = createModelElementForParent(grammarAccess.getRealTimeRule());
                    						}
                    						set(
                    							current,
                    							"execDuration",
                    							lv_execDuration_11_0,
                    							"org.rsaml.text.RsamlText.Real");
                    						afterParserOrEnumRuleCall();
                    					

                    }


                    }

                    // InternalRsamlText.g:685:4: ( (lv_timeUnit_12_0= ruleTimeUnit ) )
                    // InternalRsamlText.g:686:5: (lv_timeUnit_12_0= ruleTimeUnit )
                    {
                    // InternalRsamlText.g:686:5: (lv_timeUnit_12_0= ruleTimeUnit )
                    // InternalRsamlText.g:687:6: lv_timeUnit_12_0= ruleTimeUnit
                    {

                    						newCompositeNode(grammarAccess.getRealTimeAccess().getTimeUnitTimeUnitEnumRuleCall_4_2_0());
                    					
                    pushFollow(FOLLOW_2);
                    lv_timeUnit_12_0=ruleTimeUnit();

                    state._fsp--;


                    						if (current==null) {
                    							current = createModelElementForParent(grammarAccess.getRealTimeRule());
                    						}
                    						set(
                    							current,
                    							"timeUnit",
                    							lv_timeUnit_12_0,
                    							"org.rsaml.text.RsamlText.TimeUnit");
                    						afterParserOrEnumRuleCall();
                    					

                    }


                    }


                    }


                    }
                    break;
                case 6 :
                    // InternalRsamlText.g:706:3: this_Unit_13= ruleUnit[$current]
                    {

                    			if (current==null) {
                    				current = createModelElement(grammarAccess.getRealTimeRule());
                    			}
                    			newCompositeNode(grammarAccess.getRealTimeAccess().getUnitParserRuleCall_5());
                    		
                    pushFollow(FOLLOW_2);
                    this_Unit_13=ruleUnit(current);

                    state._fsp--;


                    			current = this_Unit_13;
                    			afterParserOrEnumRuleCall();
                    		

                    }
                    break;

            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "ruleRealTime"


    // $ANTLR start "entryRuleLayer"
    // InternalRsamlText.g:721:1: entryRuleLayer returns [EObject current=null] : iv_ruleLayer= ruleLayer EOF ;
    public final EObject entryRuleLayer() throws RecognitionException {
        EObject current = null;

        EObject iv_ruleLayer = null;


        try {
            // InternalRsamlText.g:721:46: (iv_ruleLayer= ruleLayer EOF )
            // InternalRsamlText.g:722:2: iv_ruleLayer= ruleLayer EOF
            {
             newCompositeNode(grammarAccess.getLayerRule()); 
            pushFollow(FOLLOW_1);
            iv_ruleLayer=ruleLayer();

            state._fsp--;

             current =iv_ruleLayer; 
            match(input,EOF,FOLLOW_2); 

            }

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "entryRuleLayer"


    // $ANTLR start "ruleLayer"
    // InternalRsamlText.g:728:1: ruleLayer returns [EObject current=null] : ( () otherlv_1= 'layer' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'level' ( (lv_level_6_0= ruleInteger ) ) ) | (otherlv_7= 'maxExecTime' ( (lv_maxExecTime_8_0= ruleReal ) ) ( (lv_timeUnit_9_0= ruleTimeUnit ) ) ) | this_Unit_10= ruleUnit[$current] | ( (lv_modules_11_0= ruleModule ) ) )* otherlv_12= '}' ) ;
    public final EObject ruleLayer() throws RecognitionException {
        EObject current = null;

        Token otherlv_1=null;
        Token otherlv_3=null;
        Token otherlv_5=null;
        Token otherlv_7=null;
        Token otherlv_12=null;
        AntlrDatatypeRuleToken lv_name_2_0 = null;

        EObject this_Described_4 = null;

        AntlrDatatypeRuleToken lv_level_6_0 = null;

        AntlrDatatypeRuleToken lv_maxExecTime_8_0 = null;

        Enumerator lv_timeUnit_9_0 = null;

        EObject this_Unit_10 = null;

        EObject lv_modules_11_0 = null;



        	enterRule();

        try {
            // InternalRsamlText.g:734:2: ( ( () otherlv_1= 'layer' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'level' ( (lv_level_6_0= ruleInteger ) ) ) | (otherlv_7= 'maxExecTime' ( (lv_maxExecTime_8_0= ruleReal ) ) ( (lv_timeUnit_9_0= ruleTimeUnit ) ) ) | this_Unit_10= ruleUnit[$current] | ( (lv_modules_11_0= ruleModule ) ) )* otherlv_12= '}' ) )
            // InternalRsamlText.g:735:2: ( () otherlv_1= 'layer' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'level' ( (lv_level_6_0= ruleInteger ) ) ) | (otherlv_7= 'maxExecTime' ( (lv_maxExecTime_8_0= ruleReal ) ) ( (lv_timeUnit_9_0= ruleTimeUnit ) ) ) | this_Unit_10= ruleUnit[$current] | ( (lv_modules_11_0= ruleModule ) ) )* otherlv_12= '}' )
            {
            // InternalRsamlText.g:735:2: ( () otherlv_1= 'layer' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'level' ( (lv_level_6_0= ruleInteger ) ) ) | (otherlv_7= 'maxExecTime' ( (lv_maxExecTime_8_0= ruleReal ) ) ( (lv_timeUnit_9_0= ruleTimeUnit ) ) ) | this_Unit_10= ruleUnit[$current] | ( (lv_modules_11_0= ruleModule ) ) )* otherlv_12= '}' )
            // InternalRsamlText.g:736:3: () otherlv_1= 'layer' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'level' ( (lv_level_6_0= ruleInteger ) ) ) | (otherlv_7= 'maxExecTime' ( (lv_maxExecTime_8_0= ruleReal ) ) ( (lv_timeUnit_9_0= ruleTimeUnit ) ) ) | this_Unit_10= ruleUnit[$current] | ( (lv_modules_11_0= ruleModule ) ) )* otherlv_12= '}'
            {
            // InternalRsamlText.g:736:3: ()
            // InternalRsamlText.g:737:4: 
            {

            				current = forceCreateModelElement(
            					grammarAccess.getLayerAccess().getLayerAction_0(),
            					current);
            			

            }

            otherlv_1=(Token)match(input,25,FOLLOW_3); 

            			newLeafNode(otherlv_1, grammarAccess.getLayerAccess().getLayerKeyword_1());
            		
            // InternalRsamlText.g:747:3: ( (lv_name_2_0= ruleName ) )?
            int alt4=2;
            int LA4_0 = input.LA(1);

            if ( ((LA4_0>=RULE_STRING && LA4_0<=RULE_ID)||LA4_0==11||(LA4_0>=13 && LA4_0<=16)||(LA4_0>=18 && LA4_0<=29)||(LA4_0>=31 && LA4_0<=44)||(LA4_0>=46 && LA4_0<=80)||(LA4_0>=82 && LA4_0<=118)) ) {
                alt4=1;
            }
            switch (alt4) {
                case 1 :
                    // InternalRsamlText.g:748:4: (lv_name_2_0= ruleName )
                    {
                    // InternalRsamlText.g:748:4: (lv_name_2_0= ruleName )
                    // InternalRsamlText.g:749:5: lv_name_2_0= ruleName
                    {

                    					newCompositeNode(grammarAccess.getLayerAccess().getNameNameParserRuleCall_2_0());
                    				
                    pushFollow(FOLLOW_4);
                    lv_name_2_0=ruleName();

                    state._fsp--;


                    					if (current==null) {
                    						current = createModelElementForParent(grammarAccess.getLayerRule());
                    					}
                    					set(
                    						current,
                    						"name",
                    						lv_name_2_0,
                    						"org.rsaml.text.RsamlText.Name");
                    					afterParserOrEnumRuleCall();
                    				

                    }


                    }
                    break;

            }

            otherlv_3=(Token)match(input,12,FOLLOW_15); 

            			newLeafNode(otherlv_3, grammarAccess.getLayerAccess().getLeftCurlyBracketKeyword_3());
            		
            // InternalRsamlText.g:770:3: (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'level' ( (lv_level_6_0= ruleInteger ) ) ) | (otherlv_7= 'maxExecTime' ( (lv_maxExecTime_8_0= ruleReal ) ) ( (lv_timeUnit_9_0= ruleTimeUnit ) ) ) | this_Unit_10= ruleUnit[$current] | ( (lv_modules_11_0= ruleModule ) ) )*
            loop5:
            do {
                int alt5=6;
                switch ( input.LA(1) ) {
                case 18:
                    {
                    alt5=1;
                    }
                    break;
                case 26:
                    {
                    alt5=2;
                    }
                    break;
                case 27:
                    {
                    alt5=3;
                    }
                    break;
                case 19:
                    {
                    alt5=4;
                    }
                    break;
                case 28:
                    {
                    alt5=5;
                    }
                    break;

                }

                switch (alt5) {
            	case 1 :
            	    // InternalRsamlText.g:771:4: this_Described_4= ruleDescribed[$current]
            	    {

            	    				if (current==null) {
            	    					current = createModelElement(grammarAccess.getLayerRule());
            	    				}
            	    				newCompositeNode(grammarAccess.getLayerAccess().getDescribedParserRuleCall_4_0());
            	    			
            	    pushFollow(FOLLOW_15);
            	    this_Described_4=ruleDescribed(current);

            	    state._fsp--;


            	    				current = this_Described_4;
            	    				afterParserOrEnumRuleCall();
            	    			

            	    }
            	    break;
            	case 2 :
            	    // InternalRsamlText.g:783:4: (otherlv_5= 'level' ( (lv_level_6_0= ruleInteger ) ) )
            	    {
            	    // InternalRsamlText.g:783:4: (otherlv_5= 'level' ( (lv_level_6_0= ruleInteger ) ) )
            	    // InternalRsamlText.g:784:5: otherlv_5= 'level' ( (lv_level_6_0= ruleInteger ) )
            	    {
            	    otherlv_5=(Token)match(input,26,FOLLOW_7); 

            	    					newLeafNode(otherlv_5, grammarAccess.getLayerAccess().getLevelKeyword_4_1_0());
            	    				
            	    // InternalRsamlText.g:788:5: ( (lv_level_6_0= ruleInteger ) )
            	    // InternalRsamlText.g:789:6: (lv_level_6_0= ruleInteger )
            	    {
            	    // InternalRsamlText.g:789:6: (lv_level_6_0= ruleInteger )
            	    // InternalRsamlText.g:790:7: lv_level_6_0= ruleInteger
            	    {

            	    							newCompositeNode(grammarAccess.getLayerAccess().getLevelIntegerParserRuleCall_4_1_1_0());
            	    						
            	    pushFollow(FOLLOW_15);
            	    lv_level_6_0=ruleInteger();

            	    state._fsp--;


            	    							if (current==null) {
            	    								current = createModelElementForParent(grammarAccess.getLayerRule());
            	    							}
            	    							set(
            	    								current,
            	    								"level",
            	    								lv_level_6_0,
            	    								"org.rsaml.text.RsamlText.Integer");
            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;
            	case 3 :
            	    // InternalRsamlText.g:809:4: (otherlv_7= 'maxExecTime' ( (lv_maxExecTime_8_0= ruleReal ) ) ( (lv_timeUnit_9_0= ruleTimeUnit ) ) )
            	    {
            	    // InternalRsamlText.g:809:4: (otherlv_7= 'maxExecTime' ( (lv_maxExecTime_8_0= ruleReal ) ) ( (lv_timeUnit_9_0= ruleTimeUnit ) ) )
            	    // InternalRsamlText.g:810:5: otherlv_7= 'maxExecTime' ( (lv_maxExecTime_8_0= ruleReal ) ) ( (lv_timeUnit_9_0= ruleTimeUnit ) )
            	    {
            	    otherlv_7=(Token)match(input,27,FOLLOW_14); 

            	    					newLeafNode(otherlv_7, grammarAccess.getLayerAccess().getMaxExecTimeKeyword_4_2_0());
            	    				
            	    // InternalRsamlText.g:814:5: ( (lv_maxExecTime_8_0= ruleReal ) )
            	    // InternalRsamlText.g:815:6: (lv_maxExecTime_8_0= ruleReal )
            	    {
            	    // InternalRsamlText.g:815:6: (lv_maxExecTime_8_0= ruleReal )
            	    // InternalRsamlText.g:816:7: lv_maxExecTime_8_0= ruleReal
            	    {

            	    							newCompositeNode(grammarAccess.getLayerAccess().getMaxExecTimeRealParserRuleCall_4_2_1_0());
            	    						
            	    pushFollow(FOLLOW_11);
            	    lv_maxExecTime_8_0=ruleReal();

            	    state._fsp--;


            	    							if (current==null) {
            	    								current = createModelElementForParent(grammarAccess.getLayerRule());
            	    							}
            	    							set(
            	    								current,
            	    								"maxExecTime",
            	    								lv_maxExecTime_8_0,
            	    								"org.rsaml.text.RsamlText.Real");
            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }

            	    // InternalRsamlText.g:833:5: ( (lv_timeUnit_9_0= ruleTimeUnit ) )
            	    // InternalRsamlText.g:834:6: (lv_timeUnit_9_0= ruleTimeUnit )
            	    {
            	    // InternalRsamlText.g:834:6: (lv_timeUnit_9_0= ruleTimeUnit )
            	    // InternalRsamlText.g:835:7: lv_timeUnit_9_0= ruleTimeUnit
            	    {

            	    							newCompositeNode(grammarAccess.getLayerAccess().getTimeUnitTimeUnitEnumRuleCall_4_2_2_0());
            	    						
            	    pushFollow(FOLLOW_15);
            	    lv_timeUnit_9_0=ruleTimeUnit();

            	    state._fsp--;


            	    							if (current==null) {
            	    								current = createModelElementForParent(grammarAccess.getLayerRule());
            	    							}
            	    							set(
            	    								current,
            	    								"timeUnit",
            	    								lv_timeUnit_9_0,
            	    								"org.rsaml.text.RsamlText.TimeUnit");
            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;
            	case 4 :
            	    // InternalRsamlText.g:854:4: this_Unit_10= ruleUnit[$current]
            	    {

            	    				if (current==null) {
            	    					current = createModelElement(grammarAccess.getLayerRule());
            	    				}
            	    				newCompositeNode(grammarAccess.getLayerAccess().getUnitParserRuleCall_4_3());
            	    			
            	    pushFollow(FOLLOW_15);
            	    this_Unit_10=ruleUnit(current);

            	    state._fsp--;


            	    				current = this_Unit_10;
            	    				afterParserOrEnumRuleCall();
            	    			

            	    }
            	    break;
            	case 5 :
            	    // InternalRsamlText.g:866:4: ( (lv_modules_11_0= ruleModule ) )
            	    {
            	    // InternalRsamlText.g:866:4: ( (lv_modules_11_0= ruleModule ) )
            	    // InternalRsamlText.g:867:5: (lv_modules_11_0= ruleModule )
            	    {
            	    // InternalRsamlText.g:867:5: (lv_modules_11_0= ruleModule )
            	    // InternalRsamlText.g:868:6: lv_modules_11_0= ruleModule
            	    {

            	    						newCompositeNode(grammarAccess.getLayerAccess().getModulesModuleParserRuleCall_4_4_0());
            	    					
            	    pushFollow(FOLLOW_15);
            	    lv_modules_11_0=ruleModule();

            	    state._fsp--;


            	    						if (current==null) {
            	    							current = createModelElementForParent(grammarAccess.getLayerRule());
            	    						}
            	    						add(
            	    							current,
            	    							"modules",
            	    							lv_modules_11_0,
            	    							"org.rsaml.text.RsamlText.Module");
            	    						afterParserOrEnumRuleCall();
            	    					

            	    }


            	    }


            	    }
            	    break;

            	default :
            	    break loop5;
                }
            } while (true);

            otherlv_12=(Token)match(input,17,FOLLOW_2); 

            			newLeafNode(otherlv_12, grammarAccess.getLayerAccess().getRightCurlyBracketKeyword_5());
            		

            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "ruleLayer"


    // $ANTLR start "entryRuleModule"
    // InternalRsamlText.g:894:1: entryRuleModule returns [EObject current=null] : iv_ruleModule= ruleModule EOF ;
    public final EObject entryRuleModule() throws RecognitionException {
        EObject current = null;

        EObject iv_ruleModule = null;


        try {
            // InternalRsamlText.g:894:47: (iv_ruleModule= ruleModule EOF )
            // InternalRsamlText.g:895:2: iv_ruleModule= ruleModule EOF
            {
             newCompositeNode(grammarAccess.getModuleRule()); 
            pushFollow(FOLLOW_1);
            iv_ruleModule=ruleModule();

            state._fsp--;

             current =iv_ruleModule; 
            match(input,EOF,FOLLOW_2); 

            }

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "entryRuleModule"


    // $ANTLR start "ruleModule"
    // InternalRsamlText.g:901:1: ruleModule returns [EObject current=null] : ( () otherlv_1= 'module' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | this_RealTime_5= ruleRealTime[$current] | (otherlv_6= 'sensors' ( ( ruleQualifiedName ) ) (otherlv_8= ',' ( ( ruleQualifiedName ) ) )* ) | (otherlv_10= 'actuators' ( ( ruleQualifiedName ) ) (otherlv_12= ',' ( ( ruleQualifiedName ) ) )* ) | (otherlv_14= 'lifecycle' ( (lv_lifecycle_15_0= ruleNodeLifecycle ) ) ) | ( (lv_functions_16_0= ruleFunction ) ) | ( (lv_ports_17_0= rulePort ) ) | ( (lv_inhibitors_18_0= ruleInhibitor ) ) | ( (lv_suppressors_19_0= ruleSuppressor ) ) )* otherlv_20= '}' ) ;
    public final EObject ruleModule() throws RecognitionException {
        EObject current = null;

        Token otherlv_1=null;
        Token otherlv_3=null;
        Token otherlv_6=null;
        Token otherlv_8=null;
        Token otherlv_10=null;
        Token otherlv_12=null;
        Token otherlv_14=null;
        Token otherlv_20=null;
        AntlrDatatypeRuleToken lv_name_2_0 = null;

        EObject this_Described_4 = null;

        EObject this_RealTime_5 = null;

        Enumerator lv_lifecycle_15_0 = null;

        EObject lv_functions_16_0 = null;

        EObject lv_ports_17_0 = null;

        EObject lv_inhibitors_18_0 = null;

        EObject lv_suppressors_19_0 = null;



        	enterRule();

        try {
            // InternalRsamlText.g:907:2: ( ( () otherlv_1= 'module' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | this_RealTime_5= ruleRealTime[$current] | (otherlv_6= 'sensors' ( ( ruleQualifiedName ) ) (otherlv_8= ',' ( ( ruleQualifiedName ) ) )* ) | (otherlv_10= 'actuators' ( ( ruleQualifiedName ) ) (otherlv_12= ',' ( ( ruleQualifiedName ) ) )* ) | (otherlv_14= 'lifecycle' ( (lv_lifecycle_15_0= ruleNodeLifecycle ) ) ) | ( (lv_functions_16_0= ruleFunction ) ) | ( (lv_ports_17_0= rulePort ) ) | ( (lv_inhibitors_18_0= ruleInhibitor ) ) | ( (lv_suppressors_19_0= ruleSuppressor ) ) )* otherlv_20= '}' ) )
            // InternalRsamlText.g:908:2: ( () otherlv_1= 'module' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | this_RealTime_5= ruleRealTime[$current] | (otherlv_6= 'sensors' ( ( ruleQualifiedName ) ) (otherlv_8= ',' ( ( ruleQualifiedName ) ) )* ) | (otherlv_10= 'actuators' ( ( ruleQualifiedName ) ) (otherlv_12= ',' ( ( ruleQualifiedName ) ) )* ) | (otherlv_14= 'lifecycle' ( (lv_lifecycle_15_0= ruleNodeLifecycle ) ) ) | ( (lv_functions_16_0= ruleFunction ) ) | ( (lv_ports_17_0= rulePort ) ) | ( (lv_inhibitors_18_0= ruleInhibitor ) ) | ( (lv_suppressors_19_0= ruleSuppressor ) ) )* otherlv_20= '}' )
            {
            // InternalRsamlText.g:908:2: ( () otherlv_1= 'module' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | this_RealTime_5= ruleRealTime[$current] | (otherlv_6= 'sensors' ( ( ruleQualifiedName ) ) (otherlv_8= ',' ( ( ruleQualifiedName ) ) )* ) | (otherlv_10= 'actuators' ( ( ruleQualifiedName ) ) (otherlv_12= ',' ( ( ruleQualifiedName ) ) )* ) | (otherlv_14= 'lifecycle' ( (lv_lifecycle_15_0= ruleNodeLifecycle ) ) ) | ( (lv_functions_16_0= ruleFunction ) ) | ( (lv_ports_17_0= rulePort ) ) | ( (lv_inhibitors_18_0= ruleInhibitor ) ) | ( (lv_suppressors_19_0= ruleSuppressor ) ) )* otherlv_20= '}' )
            // InternalRsamlText.g:909:3: () otherlv_1= 'module' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | this_RealTime_5= ruleRealTime[$current] | (otherlv_6= 'sensors' ( ( ruleQualifiedName ) ) (otherlv_8= ',' ( ( ruleQualifiedName ) ) )* ) | (otherlv_10= 'actuators' ( ( ruleQualifiedName ) ) (otherlv_12= ',' ( ( ruleQualifiedName ) ) )* ) | (otherlv_14= 'lifecycle' ( (lv_lifecycle_15_0= ruleNodeLifecycle ) ) ) | ( (lv_functions_16_0= ruleFunction ) ) | ( (lv_ports_17_0= rulePort ) ) | ( (lv_inhibitors_18_0= ruleInhibitor ) ) | ( (lv_suppressors_19_0= ruleSuppressor ) ) )* otherlv_20= '}'
            {
            // InternalRsamlText.g:909:3: ()
            // InternalRsamlText.g:910:4: 
            {

            				current = forceCreateModelElement(
            					grammarAccess.getModuleAccess().getModuleAction_0(),
            					current);
            			

            }

            otherlv_1=(Token)match(input,28,FOLLOW_3); 

            			newLeafNode(otherlv_1, grammarAccess.getModuleAccess().getModuleKeyword_1());
            		
            // InternalRsamlText.g:920:3: ( (lv_name_2_0= ruleName ) )?
            int alt6=2;
            int LA6_0 = input.LA(1);

            if ( ((LA6_0>=RULE_STRING && LA6_0<=RULE_ID)||LA6_0==11||(LA6_0>=13 && LA6_0<=16)||(LA6_0>=18 && LA6_0<=29)||(LA6_0>=31 && LA6_0<=44)||(LA6_0>=46 && LA6_0<=80)||(LA6_0>=82 && LA6_0<=118)) ) {
                alt6=1;
            }
            switch (alt6) {
                case 1 :
                    // InternalRsamlText.g:921:4: (lv_name_2_0= ruleName )
                    {
                    // InternalRsamlText.g:921:4: (lv_name_2_0= ruleName )
                    // InternalRsamlText.g:922:5: lv_name_2_0= ruleName
                    {

                    					newCompositeNode(grammarAccess.getModuleAccess().getNameNameParserRuleCall_2_0());
                    				
                    pushFollow(FOLLOW_4);
                    lv_name_2_0=ruleName();

                    state._fsp--;


                    					if (current==null) {
                    						current = createModelElementForParent(grammarAccess.getModuleRule());
                    					}
                    					set(
                    						current,
                    						"name",
                    						lv_name_2_0,
                    						"org.rsaml.text.RsamlText.Name");
                    					afterParserOrEnumRuleCall();
                    				

                    }


                    }
                    break;

            }

            otherlv_3=(Token)match(input,12,FOLLOW_16); 

            			newLeafNode(otherlv_3, grammarAccess.getModuleAccess().getLeftCurlyBracketKeyword_3());
            		
            // InternalRsamlText.g:943:3: (this_Described_4= ruleDescribed[$current] | this_RealTime_5= ruleRealTime[$current] | (otherlv_6= 'sensors' ( ( ruleQualifiedName ) ) (otherlv_8= ',' ( ( ruleQualifiedName ) ) )* ) | (otherlv_10= 'actuators' ( ( ruleQualifiedName ) ) (otherlv_12= ',' ( ( ruleQualifiedName ) ) )* ) | (otherlv_14= 'lifecycle' ( (lv_lifecycle_15_0= ruleNodeLifecycle ) ) ) | ( (lv_functions_16_0= ruleFunction ) ) | ( (lv_ports_17_0= rulePort ) ) | ( (lv_inhibitors_18_0= ruleInhibitor ) ) | ( (lv_suppressors_19_0= ruleSuppressor ) ) )*
            loop9:
            do {
                int alt9=10;
                switch ( input.LA(1) ) {
                case 18:
                    {
                    alt9=1;
                    }
                    break;
                case 19:
                case 20:
                case 21:
                case 22:
                case 23:
                case 24:
                    {
                    alt9=2;
                    }
                    break;
                case 29:
                    {
                    alt9=3;
                    }
                    break;
                case 31:
                    {
                    alt9=4;
                    }
                    break;
                case 15:
                    {
                    alt9=5;
                    }
                    break;
                case 32:
                    {
                    alt9=6;
                    }
                    break;
                case 39:
                case 40:
                    {
                    alt9=7;
                    }
                    break;
                case 46:
                    {
                    alt9=8;
                    }
                    break;
                case 50:
                    {
                    alt9=9;
                    }
                    break;

                }

                switch (alt9) {
            	case 1 :
            	    // InternalRsamlText.g:944:4: this_Described_4= ruleDescribed[$current]
            	    {

            	    				if (current==null) {
            	    					current = createModelElement(grammarAccess.getModuleRule());
            	    				}
            	    				newCompositeNode(grammarAccess.getModuleAccess().getDescribedParserRuleCall_4_0());
            	    			
            	    pushFollow(FOLLOW_16);
            	    this_Described_4=ruleDescribed(current);

            	    state._fsp--;


            	    				current = this_Described_4;
            	    				afterParserOrEnumRuleCall();
            	    			

            	    }
            	    break;
            	case 2 :
            	    // InternalRsamlText.g:956:4: this_RealTime_5= ruleRealTime[$current]
            	    {

            	    				if (current==null) {
            	    					current = createModelElement(grammarAccess.getModuleRule());
            	    				}
            	    				newCompositeNode(grammarAccess.getModuleAccess().getRealTimeParserRuleCall_4_1());
            	    			
            	    pushFollow(FOLLOW_16);
            	    this_RealTime_5=ruleRealTime(current);

            	    state._fsp--;


            	    				current = this_RealTime_5;
            	    				afterParserOrEnumRuleCall();
            	    			

            	    }
            	    break;
            	case 3 :
            	    // InternalRsamlText.g:968:4: (otherlv_6= 'sensors' ( ( ruleQualifiedName ) ) (otherlv_8= ',' ( ( ruleQualifiedName ) ) )* )
            	    {
            	    // InternalRsamlText.g:968:4: (otherlv_6= 'sensors' ( ( ruleQualifiedName ) ) (otherlv_8= ',' ( ( ruleQualifiedName ) ) )* )
            	    // InternalRsamlText.g:969:5: otherlv_6= 'sensors' ( ( ruleQualifiedName ) ) (otherlv_8= ',' ( ( ruleQualifiedName ) ) )*
            	    {
            	    otherlv_6=(Token)match(input,29,FOLLOW_17); 

            	    					newLeafNode(otherlv_6, grammarAccess.getModuleAccess().getSensorsKeyword_4_2_0());
            	    				
            	    // InternalRsamlText.g:973:5: ( ( ruleQualifiedName ) )
            	    // InternalRsamlText.g:974:6: ( ruleQualifiedName )
            	    {
            	    // InternalRsamlText.g:974:6: ( ruleQualifiedName )
            	    // InternalRsamlText.g:975:7: ruleQualifiedName
            	    {

            	    							if (current==null) {
            	    								current = createModelElement(grammarAccess.getModuleRule());
            	    							}
            	    						

            	    							newCompositeNode(grammarAccess.getModuleAccess().getSensorsSensorCrossReference_4_2_1_0());
            	    						
            	    pushFollow(FOLLOW_18);
            	    ruleQualifiedName();

            	    state._fsp--;


            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }

            	    // InternalRsamlText.g:989:5: (otherlv_8= ',' ( ( ruleQualifiedName ) ) )*
            	    loop7:
            	    do {
            	        int alt7=2;
            	        int LA7_0 = input.LA(1);

            	        if ( (LA7_0==30) ) {
            	            alt7=1;
            	        }


            	        switch (alt7) {
            	    	case 1 :
            	    	    // InternalRsamlText.g:990:6: otherlv_8= ',' ( ( ruleQualifiedName ) )
            	    	    {
            	    	    otherlv_8=(Token)match(input,30,FOLLOW_17); 

            	    	    						newLeafNode(otherlv_8, grammarAccess.getModuleAccess().getCommaKeyword_4_2_2_0());
            	    	    					
            	    	    // InternalRsamlText.g:994:6: ( ( ruleQualifiedName ) )
            	    	    // InternalRsamlText.g:995:7: ( ruleQualifiedName )
            	    	    {
            	    	    // InternalRsamlText.g:995:7: ( ruleQualifiedName )
            	    	    // InternalRsamlText.g:996:8: ruleQualifiedName
            	    	    {

            	    	    								if (current==null) {
            	    	    									current = createModelElement(grammarAccess.getModuleRule());
            	    	    								}
            	    	    							

            	    	    								newCompositeNode(grammarAccess.getModuleAccess().getSensorsSensorCrossReference_4_2_2_1_0());
            	    	    							
            	    	    pushFollow(FOLLOW_18);
            	    	    ruleQualifiedName();

            	    	    state._fsp--;


            	    	    								afterParserOrEnumRuleCall();
            	    	    							

            	    	    }


            	    	    }


            	    	    }
            	    	    break;

            	    	default :
            	    	    break loop7;
            	        }
            	    } while (true);


            	    }


            	    }
            	    break;
            	case 4 :
            	    // InternalRsamlText.g:1013:4: (otherlv_10= 'actuators' ( ( ruleQualifiedName ) ) (otherlv_12= ',' ( ( ruleQualifiedName ) ) )* )
            	    {
            	    // InternalRsamlText.g:1013:4: (otherlv_10= 'actuators' ( ( ruleQualifiedName ) ) (otherlv_12= ',' ( ( ruleQualifiedName ) ) )* )
            	    // InternalRsamlText.g:1014:5: otherlv_10= 'actuators' ( ( ruleQualifiedName ) ) (otherlv_12= ',' ( ( ruleQualifiedName ) ) )*
            	    {
            	    otherlv_10=(Token)match(input,31,FOLLOW_17); 

            	    					newLeafNode(otherlv_10, grammarAccess.getModuleAccess().getActuatorsKeyword_4_3_0());
            	    				
            	    // InternalRsamlText.g:1018:5: ( ( ruleQualifiedName ) )
            	    // InternalRsamlText.g:1019:6: ( ruleQualifiedName )
            	    {
            	    // InternalRsamlText.g:1019:6: ( ruleQualifiedName )
            	    // InternalRsamlText.g:1020:7: ruleQualifiedName
            	    {

            	    							if (current==null) {
            	    								current = createModelElement(grammarAccess.getModuleRule());
            	    							}
            	    						

            	    							newCompositeNode(grammarAccess.getModuleAccess().getActuatorsActuatorCrossReference_4_3_1_0());
            	    						
            	    pushFollow(FOLLOW_18);
            	    ruleQualifiedName();

            	    state._fsp--;


            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }

            	    // InternalRsamlText.g:1034:5: (otherlv_12= ',' ( ( ruleQualifiedName ) ) )*
            	    loop8:
            	    do {
            	        int alt8=2;
            	        int LA8_0 = input.LA(1);

            	        if ( (LA8_0==30) ) {
            	            alt8=1;
            	        }


            	        switch (alt8) {
            	    	case 1 :
            	    	    // InternalRsamlText.g:1035:6: otherlv_12= ',' ( ( ruleQualifiedName ) )
            	    	    {
            	    	    otherlv_12=(Token)match(input,30,FOLLOW_17); 

            	    	    						newLeafNode(otherlv_12, grammarAccess.getModuleAccess().getCommaKeyword_4_3_2_0());
            	    	    					
            	    	    // InternalRsamlText.g:1039:6: ( ( ruleQualifiedName ) )
            	    	    // InternalRsamlText.g:1040:7: ( ruleQualifiedName )
            	    	    {
            	    	    // InternalRsamlText.g:1040:7: ( ruleQualifiedName )
            	    	    // InternalRsamlText.g:1041:8: ruleQualifiedName
            	    	    {

            	    	    								if (current==null) {
            	    	    									current = createModelElement(grammarAccess.getModuleRule());
            	    	    								}
            	    	    							

            	    	    								newCompositeNode(grammarAccess.getModuleAccess().getActuatorsActuatorCrossReference_4_3_2_1_0());
            	    	    							
            	    	    pushFollow(FOLLOW_18);
            	    	    ruleQualifiedName();

            	    	    state._fsp--;


            	    	    								afterParserOrEnumRuleCall();
            	    	    							

            	    	    }


            	    	    }


            	    	    }
            	    	    break;

            	    	default :
            	    	    break loop8;
            	        }
            	    } while (true);


            	    }


            	    }
            	    break;
            	case 5 :
            	    // InternalRsamlText.g:1058:4: (otherlv_14= 'lifecycle' ( (lv_lifecycle_15_0= ruleNodeLifecycle ) ) )
            	    {
            	    // InternalRsamlText.g:1058:4: (otherlv_14= 'lifecycle' ( (lv_lifecycle_15_0= ruleNodeLifecycle ) ) )
            	    // InternalRsamlText.g:1059:5: otherlv_14= 'lifecycle' ( (lv_lifecycle_15_0= ruleNodeLifecycle ) )
            	    {
            	    otherlv_14=(Token)match(input,15,FOLLOW_8); 

            	    					newLeafNode(otherlv_14, grammarAccess.getModuleAccess().getLifecycleKeyword_4_4_0());
            	    				
            	    // InternalRsamlText.g:1063:5: ( (lv_lifecycle_15_0= ruleNodeLifecycle ) )
            	    // InternalRsamlText.g:1064:6: (lv_lifecycle_15_0= ruleNodeLifecycle )
            	    {
            	    // InternalRsamlText.g:1064:6: (lv_lifecycle_15_0= ruleNodeLifecycle )
            	    // InternalRsamlText.g:1065:7: lv_lifecycle_15_0= ruleNodeLifecycle
            	    {

            	    							newCompositeNode(grammarAccess.getModuleAccess().getLifecycleNodeLifecycleEnumRuleCall_4_4_1_0());
            	    						
            	    pushFollow(FOLLOW_16);
            	    lv_lifecycle_15_0=ruleNodeLifecycle();

            	    state._fsp--;


            	    							if (current==null) {
            	    								current = createModelElementForParent(grammarAccess.getModuleRule());
            	    							}
            	    							set(
            	    								current,
            	    								"lifecycle",
            	    								lv_lifecycle_15_0,
            	    								"org.rsaml.text.RsamlText.NodeLifecycle");
            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;
            	case 6 :
            	    // InternalRsamlText.g:1084:4: ( (lv_functions_16_0= ruleFunction ) )
            	    {
            	    // InternalRsamlText.g:1084:4: ( (lv_functions_16_0= ruleFunction ) )
            	    // InternalRsamlText.g:1085:5: (lv_functions_16_0= ruleFunction )
            	    {
            	    // InternalRsamlText.g:1085:5: (lv_functions_16_0= ruleFunction )
            	    // InternalRsamlText.g:1086:6: lv_functions_16_0= ruleFunction
            	    {

            	    						newCompositeNode(grammarAccess.getModuleAccess().getFunctionsFunctionParserRuleCall_4_5_0());
            	    					
            	    pushFollow(FOLLOW_16);
            	    lv_functions_16_0=ruleFunction();

            	    state._fsp--;


            	    						if (current==null) {
            	    							current = createModelElementForParent(grammarAccess.getModuleRule());
            	    						}
            	    						add(
            	    							current,
            	    							"functions",
            	    							lv_functions_16_0,
            	    							"org.rsaml.text.RsamlText.Function");
            	    						afterParserOrEnumRuleCall();
            	    					

            	    }


            	    }


            	    }
            	    break;
            	case 7 :
            	    // InternalRsamlText.g:1104:4: ( (lv_ports_17_0= rulePort ) )
            	    {
            	    // InternalRsamlText.g:1104:4: ( (lv_ports_17_0= rulePort ) )
            	    // InternalRsamlText.g:1105:5: (lv_ports_17_0= rulePort )
            	    {
            	    // InternalRsamlText.g:1105:5: (lv_ports_17_0= rulePort )
            	    // InternalRsamlText.g:1106:6: lv_ports_17_0= rulePort
            	    {

            	    						newCompositeNode(grammarAccess.getModuleAccess().getPortsPortParserRuleCall_4_6_0());
            	    					
            	    pushFollow(FOLLOW_16);
            	    lv_ports_17_0=rulePort();

            	    state._fsp--;


            	    						if (current==null) {
            	    							current = createModelElementForParent(grammarAccess.getModuleRule());
            	    						}
            	    						add(
            	    							current,
            	    							"ports",
            	    							lv_ports_17_0,
            	    							"org.rsaml.text.RsamlText.Port");
            	    						afterParserOrEnumRuleCall();
            	    					

            	    }


            	    }


            	    }
            	    break;
            	case 8 :
            	    // InternalRsamlText.g:1124:4: ( (lv_inhibitors_18_0= ruleInhibitor ) )
            	    {
            	    // InternalRsamlText.g:1124:4: ( (lv_inhibitors_18_0= ruleInhibitor ) )
            	    // InternalRsamlText.g:1125:5: (lv_inhibitors_18_0= ruleInhibitor )
            	    {
            	    // InternalRsamlText.g:1125:5: (lv_inhibitors_18_0= ruleInhibitor )
            	    // InternalRsamlText.g:1126:6: lv_inhibitors_18_0= ruleInhibitor
            	    {

            	    						newCompositeNode(grammarAccess.getModuleAccess().getInhibitorsInhibitorParserRuleCall_4_7_0());
            	    					
            	    pushFollow(FOLLOW_16);
            	    lv_inhibitors_18_0=ruleInhibitor();

            	    state._fsp--;


            	    						if (current==null) {
            	    							current = createModelElementForParent(grammarAccess.getModuleRule());
            	    						}
            	    						add(
            	    							current,
            	    							"inhibitors",
            	    							lv_inhibitors_18_0,
            	    							"org.rsaml.text.RsamlText.Inhibitor");
            	    						afterParserOrEnumRuleCall();
            	    					

            	    }


            	    }


            	    }
            	    break;
            	case 9 :
            	    // InternalRsamlText.g:1144:4: ( (lv_suppressors_19_0= ruleSuppressor ) )
            	    {
            	    // InternalRsamlText.g:1144:4: ( (lv_suppressors_19_0= ruleSuppressor ) )
            	    // InternalRsamlText.g:1145:5: (lv_suppressors_19_0= ruleSuppressor )
            	    {
            	    // InternalRsamlText.g:1145:5: (lv_suppressors_19_0= ruleSuppressor )
            	    // InternalRsamlText.g:1146:6: lv_suppressors_19_0= ruleSuppressor
            	    {

            	    						newCompositeNode(grammarAccess.getModuleAccess().getSuppressorsSuppressorParserRuleCall_4_8_0());
            	    					
            	    pushFollow(FOLLOW_16);
            	    lv_suppressors_19_0=ruleSuppressor();

            	    state._fsp--;


            	    						if (current==null) {
            	    							current = createModelElementForParent(grammarAccess.getModuleRule());
            	    						}
            	    						add(
            	    							current,
            	    							"suppressors",
            	    							lv_suppressors_19_0,
            	    							"org.rsaml.text.RsamlText.Suppressor");
            	    						afterParserOrEnumRuleCall();
            	    					

            	    }


            	    }


            	    }
            	    break;

            	default :
            	    break loop9;
                }
            } while (true);

            otherlv_20=(Token)match(input,17,FOLLOW_2); 

            			newLeafNode(otherlv_20, grammarAccess.getModuleAccess().getRightCurlyBracketKeyword_5());
            		

            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "ruleModule"


    // $ANTLR start "entryRuleFunction"
    // InternalRsamlText.g:1172:1: entryRuleFunction returns [EObject current=null] : iv_ruleFunction= ruleFunction EOF ;
    public final EObject entryRuleFunction() throws RecognitionException {
        EObject current = null;

        EObject iv_ruleFunction = null;


        try {
            // InternalRsamlText.g:1172:49: (iv_ruleFunction= ruleFunction EOF )
            // InternalRsamlText.g:1173:2: iv_ruleFunction= ruleFunction EOF
            {
             newCompositeNode(grammarAccess.getFunctionRule()); 
            pushFollow(FOLLOW_1);
            iv_ruleFunction=ruleFunction();

            state._fsp--;

             current =iv_ruleFunction; 
            match(input,EOF,FOLLOW_2); 

            }

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "entryRuleFunction"


    // $ANTLR start "ruleFunction"
    // InternalRsamlText.g:1179:1: ruleFunction returns [EObject current=null] : ( () otherlv_1= 'function' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | this_RealTime_5= ruleRealTime[$current] | (otherlv_6= 'synchroType' ( (lv_synchroType_7_0= ruleSynchronisationType ) ) ) | (otherlv_8= 'schedPolicy' ( (lv_schedPolicy_9_0= ruleSchedulingPolicy ) ) ) | (otherlv_10= 'otherPolicy' ( (lv_otherPolicy_11_0= RULE_STRING ) ) ) | ( (lv_actions_12_0= ruleAction ) ) )* otherlv_13= '}' ) ;
    public final EObject ruleFunction() throws RecognitionException {
        EObject current = null;

        Token otherlv_1=null;
        Token otherlv_3=null;
        Token otherlv_6=null;
        Token otherlv_8=null;
        Token otherlv_10=null;
        Token lv_otherPolicy_11_0=null;
        Token otherlv_13=null;
        AntlrDatatypeRuleToken lv_name_2_0 = null;

        EObject this_Described_4 = null;

        EObject this_RealTime_5 = null;

        Enumerator lv_synchroType_7_0 = null;

        Enumerator lv_schedPolicy_9_0 = null;

        EObject lv_actions_12_0 = null;



        	enterRule();

        try {
            // InternalRsamlText.g:1185:2: ( ( () otherlv_1= 'function' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | this_RealTime_5= ruleRealTime[$current] | (otherlv_6= 'synchroType' ( (lv_synchroType_7_0= ruleSynchronisationType ) ) ) | (otherlv_8= 'schedPolicy' ( (lv_schedPolicy_9_0= ruleSchedulingPolicy ) ) ) | (otherlv_10= 'otherPolicy' ( (lv_otherPolicy_11_0= RULE_STRING ) ) ) | ( (lv_actions_12_0= ruleAction ) ) )* otherlv_13= '}' ) )
            // InternalRsamlText.g:1186:2: ( () otherlv_1= 'function' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | this_RealTime_5= ruleRealTime[$current] | (otherlv_6= 'synchroType' ( (lv_synchroType_7_0= ruleSynchronisationType ) ) ) | (otherlv_8= 'schedPolicy' ( (lv_schedPolicy_9_0= ruleSchedulingPolicy ) ) ) | (otherlv_10= 'otherPolicy' ( (lv_otherPolicy_11_0= RULE_STRING ) ) ) | ( (lv_actions_12_0= ruleAction ) ) )* otherlv_13= '}' )
            {
            // InternalRsamlText.g:1186:2: ( () otherlv_1= 'function' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | this_RealTime_5= ruleRealTime[$current] | (otherlv_6= 'synchroType' ( (lv_synchroType_7_0= ruleSynchronisationType ) ) ) | (otherlv_8= 'schedPolicy' ( (lv_schedPolicy_9_0= ruleSchedulingPolicy ) ) ) | (otherlv_10= 'otherPolicy' ( (lv_otherPolicy_11_0= RULE_STRING ) ) ) | ( (lv_actions_12_0= ruleAction ) ) )* otherlv_13= '}' )
            // InternalRsamlText.g:1187:3: () otherlv_1= 'function' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | this_RealTime_5= ruleRealTime[$current] | (otherlv_6= 'synchroType' ( (lv_synchroType_7_0= ruleSynchronisationType ) ) ) | (otherlv_8= 'schedPolicy' ( (lv_schedPolicy_9_0= ruleSchedulingPolicy ) ) ) | (otherlv_10= 'otherPolicy' ( (lv_otherPolicy_11_0= RULE_STRING ) ) ) | ( (lv_actions_12_0= ruleAction ) ) )* otherlv_13= '}'
            {
            // InternalRsamlText.g:1187:3: ()
            // InternalRsamlText.g:1188:4: 
            {

            				current = forceCreateModelElement(
            					grammarAccess.getFunctionAccess().getFunctionAction_0(),
            					current);
            			

            }

            otherlv_1=(Token)match(input,32,FOLLOW_3); 

            			newLeafNode(otherlv_1, grammarAccess.getFunctionAccess().getFunctionKeyword_1());
            		
            // InternalRsamlText.g:1198:3: ( (lv_name_2_0= ruleName ) )?
            int alt10=2;
            int LA10_0 = input.LA(1);

            if ( ((LA10_0>=RULE_STRING && LA10_0<=RULE_ID)||LA10_0==11||(LA10_0>=13 && LA10_0<=16)||(LA10_0>=18 && LA10_0<=29)||(LA10_0>=31 && LA10_0<=44)||(LA10_0>=46 && LA10_0<=80)||(LA10_0>=82 && LA10_0<=118)) ) {
                alt10=1;
            }
            switch (alt10) {
                case 1 :
                    // InternalRsamlText.g:1199:4: (lv_name_2_0= ruleName )
                    {
                    // InternalRsamlText.g:1199:4: (lv_name_2_0= ruleName )
                    // InternalRsamlText.g:1200:5: lv_name_2_0= ruleName
                    {

                    					newCompositeNode(grammarAccess.getFunctionAccess().getNameNameParserRuleCall_2_0());
                    				
                    pushFollow(FOLLOW_4);
                    lv_name_2_0=ruleName();

                    state._fsp--;


                    					if (current==null) {
                    						current = createModelElementForParent(grammarAccess.getFunctionRule());
                    					}
                    					set(
                    						current,
                    						"name",
                    						lv_name_2_0,
                    						"org.rsaml.text.RsamlText.Name");
                    					afterParserOrEnumRuleCall();
                    				

                    }


                    }
                    break;

            }

            otherlv_3=(Token)match(input,12,FOLLOW_19); 

            			newLeafNode(otherlv_3, grammarAccess.getFunctionAccess().getLeftCurlyBracketKeyword_3());
            		
            // InternalRsamlText.g:1221:3: (this_Described_4= ruleDescribed[$current] | this_RealTime_5= ruleRealTime[$current] | (otherlv_6= 'synchroType' ( (lv_synchroType_7_0= ruleSynchronisationType ) ) ) | (otherlv_8= 'schedPolicy' ( (lv_schedPolicy_9_0= ruleSchedulingPolicy ) ) ) | (otherlv_10= 'otherPolicy' ( (lv_otherPolicy_11_0= RULE_STRING ) ) ) | ( (lv_actions_12_0= ruleAction ) ) )*
            loop11:
            do {
                int alt11=7;
                switch ( input.LA(1) ) {
                case 18:
                    {
                    alt11=1;
                    }
                    break;
                case 19:
                case 20:
                case 21:
                case 22:
                case 23:
                case 24:
                    {
                    alt11=2;
                    }
                    break;
                case 33:
                    {
                    alt11=3;
                    }
                    break;
                case 34:
                    {
                    alt11=4;
                    }
                    break;
                case 35:
                    {
                    alt11=5;
                    }
                    break;
                case 36:
                case 37:
                    {
                    alt11=6;
                    }
                    break;

                }

                switch (alt11) {
            	case 1 :
            	    // InternalRsamlText.g:1222:4: this_Described_4= ruleDescribed[$current]
            	    {

            	    				if (current==null) {
            	    					current = createModelElement(grammarAccess.getFunctionRule());
            	    				}
            	    				newCompositeNode(grammarAccess.getFunctionAccess().getDescribedParserRuleCall_4_0());
            	    			
            	    pushFollow(FOLLOW_19);
            	    this_Described_4=ruleDescribed(current);

            	    state._fsp--;


            	    				current = this_Described_4;
            	    				afterParserOrEnumRuleCall();
            	    			

            	    }
            	    break;
            	case 2 :
            	    // InternalRsamlText.g:1234:4: this_RealTime_5= ruleRealTime[$current]
            	    {

            	    				if (current==null) {
            	    					current = createModelElement(grammarAccess.getFunctionRule());
            	    				}
            	    				newCompositeNode(grammarAccess.getFunctionAccess().getRealTimeParserRuleCall_4_1());
            	    			
            	    pushFollow(FOLLOW_19);
            	    this_RealTime_5=ruleRealTime(current);

            	    state._fsp--;


            	    				current = this_RealTime_5;
            	    				afterParserOrEnumRuleCall();
            	    			

            	    }
            	    break;
            	case 3 :
            	    // InternalRsamlText.g:1246:4: (otherlv_6= 'synchroType' ( (lv_synchroType_7_0= ruleSynchronisationType ) ) )
            	    {
            	    // InternalRsamlText.g:1246:4: (otherlv_6= 'synchroType' ( (lv_synchroType_7_0= ruleSynchronisationType ) ) )
            	    // InternalRsamlText.g:1247:5: otherlv_6= 'synchroType' ( (lv_synchroType_7_0= ruleSynchronisationType ) )
            	    {
            	    otherlv_6=(Token)match(input,33,FOLLOW_20); 

            	    					newLeafNode(otherlv_6, grammarAccess.getFunctionAccess().getSynchroTypeKeyword_4_2_0());
            	    				
            	    // InternalRsamlText.g:1251:5: ( (lv_synchroType_7_0= ruleSynchronisationType ) )
            	    // InternalRsamlText.g:1252:6: (lv_synchroType_7_0= ruleSynchronisationType )
            	    {
            	    // InternalRsamlText.g:1252:6: (lv_synchroType_7_0= ruleSynchronisationType )
            	    // InternalRsamlText.g:1253:7: lv_synchroType_7_0= ruleSynchronisationType
            	    {

            	    							newCompositeNode(grammarAccess.getFunctionAccess().getSynchroTypeSynchronisationTypeEnumRuleCall_4_2_1_0());
            	    						
            	    pushFollow(FOLLOW_19);
            	    lv_synchroType_7_0=ruleSynchronisationType();

            	    state._fsp--;


            	    							if (current==null) {
            	    								current = createModelElementForParent(grammarAccess.getFunctionRule());
            	    							}
            	    							set(
            	    								current,
            	    								"synchroType",
            	    								lv_synchroType_7_0,
            	    								"org.rsaml.text.RsamlText.SynchronisationType");
            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;
            	case 4 :
            	    // InternalRsamlText.g:1272:4: (otherlv_8= 'schedPolicy' ( (lv_schedPolicy_9_0= ruleSchedulingPolicy ) ) )
            	    {
            	    // InternalRsamlText.g:1272:4: (otherlv_8= 'schedPolicy' ( (lv_schedPolicy_9_0= ruleSchedulingPolicy ) ) )
            	    // InternalRsamlText.g:1273:5: otherlv_8= 'schedPolicy' ( (lv_schedPolicy_9_0= ruleSchedulingPolicy ) )
            	    {
            	    otherlv_8=(Token)match(input,34,FOLLOW_21); 

            	    					newLeafNode(otherlv_8, grammarAccess.getFunctionAccess().getSchedPolicyKeyword_4_3_0());
            	    				
            	    // InternalRsamlText.g:1277:5: ( (lv_schedPolicy_9_0= ruleSchedulingPolicy ) )
            	    // InternalRsamlText.g:1278:6: (lv_schedPolicy_9_0= ruleSchedulingPolicy )
            	    {
            	    // InternalRsamlText.g:1278:6: (lv_schedPolicy_9_0= ruleSchedulingPolicy )
            	    // InternalRsamlText.g:1279:7: lv_schedPolicy_9_0= ruleSchedulingPolicy
            	    {

            	    							newCompositeNode(grammarAccess.getFunctionAccess().getSchedPolicySchedulingPolicyEnumRuleCall_4_3_1_0());
            	    						
            	    pushFollow(FOLLOW_19);
            	    lv_schedPolicy_9_0=ruleSchedulingPolicy();

            	    state._fsp--;


            	    							if (current==null) {
            	    								current = createModelElementForParent(grammarAccess.getFunctionRule());
            	    							}
            	    							set(
            	    								current,
            	    								"schedPolicy",
            	    								lv_schedPolicy_9_0,
            	    								"org.rsaml.text.RsamlText.SchedulingPolicy");
            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;
            	case 5 :
            	    // InternalRsamlText.g:1298:4: (otherlv_10= 'otherPolicy' ( (lv_otherPolicy_11_0= RULE_STRING ) ) )
            	    {
            	    // InternalRsamlText.g:1298:4: (otherlv_10= 'otherPolicy' ( (lv_otherPolicy_11_0= RULE_STRING ) ) )
            	    // InternalRsamlText.g:1299:5: otherlv_10= 'otherPolicy' ( (lv_otherPolicy_11_0= RULE_STRING ) )
            	    {
            	    otherlv_10=(Token)match(input,35,FOLLOW_10); 

            	    					newLeafNode(otherlv_10, grammarAccess.getFunctionAccess().getOtherPolicyKeyword_4_4_0());
            	    				
            	    // InternalRsamlText.g:1303:5: ( (lv_otherPolicy_11_0= RULE_STRING ) )
            	    // InternalRsamlText.g:1304:6: (lv_otherPolicy_11_0= RULE_STRING )
            	    {
            	    // InternalRsamlText.g:1304:6: (lv_otherPolicy_11_0= RULE_STRING )
            	    // InternalRsamlText.g:1305:7: lv_otherPolicy_11_0= RULE_STRING
            	    {
            	    lv_otherPolicy_11_0=(Token)match(input,RULE_STRING,FOLLOW_19); 

            	    							newLeafNode(lv_otherPolicy_11_0, grammarAccess.getFunctionAccess().getOtherPolicySTRINGTerminalRuleCall_4_4_1_0());
            	    						

            	    							if (current==null) {
            	    								current = createModelElement(grammarAccess.getFunctionRule());
            	    							}
            	    							setWithLastConsumed(
            	    								current,
            	    								"otherPolicy",
            	    								lv_otherPolicy_11_0,
            	    								"org.rsaml.text.RsamlText.STRING");
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;
            	case 6 :
            	    // InternalRsamlText.g:1323:4: ( (lv_actions_12_0= ruleAction ) )
            	    {
            	    // InternalRsamlText.g:1323:4: ( (lv_actions_12_0= ruleAction ) )
            	    // InternalRsamlText.g:1324:5: (lv_actions_12_0= ruleAction )
            	    {
            	    // InternalRsamlText.g:1324:5: (lv_actions_12_0= ruleAction )
            	    // InternalRsamlText.g:1325:6: lv_actions_12_0= ruleAction
            	    {

            	    						newCompositeNode(grammarAccess.getFunctionAccess().getActionsActionParserRuleCall_4_5_0());
            	    					
            	    pushFollow(FOLLOW_19);
            	    lv_actions_12_0=ruleAction();

            	    state._fsp--;


            	    						if (current==null) {
            	    							current = createModelElementForParent(grammarAccess.getFunctionRule());
            	    						}
            	    						add(
            	    							current,
            	    							"actions",
            	    							lv_actions_12_0,
            	    							"org.rsaml.text.RsamlText.Action");
            	    						afterParserOrEnumRuleCall();
            	    					

            	    }


            	    }


            	    }
            	    break;

            	default :
            	    break loop11;
                }
            } while (true);

            otherlv_13=(Token)match(input,17,FOLLOW_2); 

            			newLeafNode(otherlv_13, grammarAccess.getFunctionAccess().getRightCurlyBracketKeyword_5());
            		

            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "ruleFunction"


    // $ANTLR start "entryRuleAction"
    // InternalRsamlText.g:1351:1: entryRuleAction returns [EObject current=null] : iv_ruleAction= ruleAction EOF ;
    public final EObject entryRuleAction() throws RecognitionException {
        EObject current = null;

        EObject iv_ruleAction = null;


        try {
            // InternalRsamlText.g:1351:47: (iv_ruleAction= ruleAction EOF )
            // InternalRsamlText.g:1352:2: iv_ruleAction= ruleAction EOF
            {
             newCompositeNode(grammarAccess.getActionRule()); 
            pushFollow(FOLLOW_1);
            iv_ruleAction=ruleAction();

            state._fsp--;

             current =iv_ruleAction; 
            match(input,EOF,FOLLOW_2); 

            }

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "entryRuleAction"


    // $ANTLR start "ruleAction"
    // InternalRsamlText.g:1358:1: ruleAction returns [EObject current=null] : ( ( ( () otherlv_1= 'action' ) | ( () otherlv_3= 'rtAction' ) ) ( (lv_name_4_0= ruleName ) )? otherlv_5= '{' (this_Described_6= ruleDescribed[$current] | this_RealTime_7= ruleRealTime[$current] | (otherlv_8= 'start' ( (lv_startDate_9_0= ruleReal ) ) ( (lv_timeUnit_10_0= ruleTimeUnit ) ) ) )* otherlv_11= '}' ) ;
    public final EObject ruleAction() throws RecognitionException {
        EObject current = null;

        Token otherlv_1=null;
        Token otherlv_3=null;
        Token otherlv_5=null;
        Token otherlv_8=null;
        Token otherlv_11=null;
        AntlrDatatypeRuleToken lv_name_4_0 = null;

        EObject this_Described_6 = null;

        EObject this_RealTime_7 = null;

        AntlrDatatypeRuleToken lv_startDate_9_0 = null;

        Enumerator lv_timeUnit_10_0 = null;



        	enterRule();

        try {
            // InternalRsamlText.g:1364:2: ( ( ( ( () otherlv_1= 'action' ) | ( () otherlv_3= 'rtAction' ) ) ( (lv_name_4_0= ruleName ) )? otherlv_5= '{' (this_Described_6= ruleDescribed[$current] | this_RealTime_7= ruleRealTime[$current] | (otherlv_8= 'start' ( (lv_startDate_9_0= ruleReal ) ) ( (lv_timeUnit_10_0= ruleTimeUnit ) ) ) )* otherlv_11= '}' ) )
            // InternalRsamlText.g:1365:2: ( ( ( () otherlv_1= 'action' ) | ( () otherlv_3= 'rtAction' ) ) ( (lv_name_4_0= ruleName ) )? otherlv_5= '{' (this_Described_6= ruleDescribed[$current] | this_RealTime_7= ruleRealTime[$current] | (otherlv_8= 'start' ( (lv_startDate_9_0= ruleReal ) ) ( (lv_timeUnit_10_0= ruleTimeUnit ) ) ) )* otherlv_11= '}' )
            {
            // InternalRsamlText.g:1365:2: ( ( ( () otherlv_1= 'action' ) | ( () otherlv_3= 'rtAction' ) ) ( (lv_name_4_0= ruleName ) )? otherlv_5= '{' (this_Described_6= ruleDescribed[$current] | this_RealTime_7= ruleRealTime[$current] | (otherlv_8= 'start' ( (lv_startDate_9_0= ruleReal ) ) ( (lv_timeUnit_10_0= ruleTimeUnit ) ) ) )* otherlv_11= '}' )
            // InternalRsamlText.g:1366:3: ( ( () otherlv_1= 'action' ) | ( () otherlv_3= 'rtAction' ) ) ( (lv_name_4_0= ruleName ) )? otherlv_5= '{' (this_Described_6= ruleDescribed[$current] | this_RealTime_7= ruleRealTime[$current] | (otherlv_8= 'start' ( (lv_startDate_9_0= ruleReal ) ) ( (lv_timeUnit_10_0= ruleTimeUnit ) ) ) )* otherlv_11= '}'
            {
            // InternalRsamlText.g:1366:3: ( ( () otherlv_1= 'action' ) | ( () otherlv_3= 'rtAction' ) )
            int alt12=2;
            int LA12_0 = input.LA(1);

            if ( (LA12_0==36) ) {
                alt12=1;
            }
            else if ( (LA12_0==37) ) {
                alt12=2;
            }
            else {
                NoViableAltException nvae =
                    new NoViableAltException("", 12, 0, input);

                throw nvae;
            }
            switch (alt12) {
                case 1 :
                    // InternalRsamlText.g:1367:4: ( () otherlv_1= 'action' )
                    {
                    // InternalRsamlText.g:1367:4: ( () otherlv_1= 'action' )
                    // InternalRsamlText.g:1368:5: () otherlv_1= 'action'
                    {
                    // InternalRsamlText.g:1368:5: ()
                    // InternalRsamlText.g:1369:6: 
                    {

                    						current = forceCreateModelElement(
                    							grammarAccess.getActionAccess().getActionAction_0_0_0(),
                    							current);
                    					

                    }

                    otherlv_1=(Token)match(input,36,FOLLOW_3); 

                    					newLeafNode(otherlv_1, grammarAccess.getActionAccess().getActionKeyword_0_0_1());
                    				

                    }


                    }
                    break;
                case 2 :
                    // InternalRsamlText.g:1381:4: ( () otherlv_3= 'rtAction' )
                    {
                    // InternalRsamlText.g:1381:4: ( () otherlv_3= 'rtAction' )
                    // InternalRsamlText.g:1382:5: () otherlv_3= 'rtAction'
                    {
                    // InternalRsamlText.g:1382:5: ()
                    // InternalRsamlText.g:1383:6: 
                    {

                    						current = forceCreateModelElement(
                    							grammarAccess.getActionAccess().getRTActionAction_0_1_0(),
                    							current);
                    					

                    }

                    otherlv_3=(Token)match(input,37,FOLLOW_3); 

                    					newLeafNode(otherlv_3, grammarAccess.getActionAccess().getRtActionKeyword_0_1_1());
                    				

                    }


                    }
                    break;

            }

            // InternalRsamlText.g:1395:3: ( (lv_name_4_0= ruleName ) )?
            int alt13=2;
            int LA13_0 = input.LA(1);

            if ( ((LA13_0>=RULE_STRING && LA13_0<=RULE_ID)||LA13_0==11||(LA13_0>=13 && LA13_0<=16)||(LA13_0>=18 && LA13_0<=29)||(LA13_0>=31 && LA13_0<=44)||(LA13_0>=46 && LA13_0<=80)||(LA13_0>=82 && LA13_0<=118)) ) {
                alt13=1;
            }
            switch (alt13) {
                case 1 :
                    // InternalRsamlText.g:1396:4: (lv_name_4_0= ruleName )
                    {
                    // InternalRsamlText.g:1396:4: (lv_name_4_0= ruleName )
                    // InternalRsamlText.g:1397:5: lv_name_4_0= ruleName
                    {

                    					newCompositeNode(grammarAccess.getActionAccess().getNameNameParserRuleCall_1_0());
                    				
                    pushFollow(FOLLOW_4);
                    lv_name_4_0=ruleName();

                    state._fsp--;


                    					if (current==null) {
                    						current = createModelElementForParent(grammarAccess.getActionRule());
                    					}
                    					set(
                    						current,
                    						"name",
                    						lv_name_4_0,
                    						"org.rsaml.text.RsamlText.Name");
                    					afterParserOrEnumRuleCall();
                    				

                    }


                    }
                    break;

            }

            otherlv_5=(Token)match(input,12,FOLLOW_22); 

            			newLeafNode(otherlv_5, grammarAccess.getActionAccess().getLeftCurlyBracketKeyword_2());
            		
            // InternalRsamlText.g:1418:3: (this_Described_6= ruleDescribed[$current] | this_RealTime_7= ruleRealTime[$current] | (otherlv_8= 'start' ( (lv_startDate_9_0= ruleReal ) ) ( (lv_timeUnit_10_0= ruleTimeUnit ) ) ) )*
            loop14:
            do {
                int alt14=4;
                switch ( input.LA(1) ) {
                case 18:
                    {
                    alt14=1;
                    }
                    break;
                case 19:
                case 20:
                case 21:
                case 22:
                case 23:
                case 24:
                    {
                    alt14=2;
                    }
                    break;
                case 38:
                    {
                    alt14=3;
                    }
                    break;

                }

                switch (alt14) {
            	case 1 :
            	    // InternalRsamlText.g:1419:4: this_Described_6= ruleDescribed[$current]
            	    {

            	    				if (current==null) {
            	    					current = createModelElement(grammarAccess.getActionRule());
            	    				}
            	    				newCompositeNode(grammarAccess.getActionAccess().getDescribedParserRuleCall_3_0());
            	    			
            	    pushFollow(FOLLOW_22);
            	    this_Described_6=ruleDescribed(current);

            	    state._fsp--;


            	    				current = this_Described_6;
            	    				afterParserOrEnumRuleCall();
            	    			

            	    }
            	    break;
            	case 2 :
            	    // InternalRsamlText.g:1431:4: this_RealTime_7= ruleRealTime[$current]
            	    {

            	    				if (current==null) {
            	    					current = createModelElement(grammarAccess.getActionRule());
            	    				}
            	    				newCompositeNode(grammarAccess.getActionAccess().getRealTimeParserRuleCall_3_1());
            	    			
            	    pushFollow(FOLLOW_22);
            	    this_RealTime_7=ruleRealTime(current);

            	    state._fsp--;


            	    				current = this_RealTime_7;
            	    				afterParserOrEnumRuleCall();
            	    			

            	    }
            	    break;
            	case 3 :
            	    // InternalRsamlText.g:1443:4: (otherlv_8= 'start' ( (lv_startDate_9_0= ruleReal ) ) ( (lv_timeUnit_10_0= ruleTimeUnit ) ) )
            	    {
            	    // InternalRsamlText.g:1443:4: (otherlv_8= 'start' ( (lv_startDate_9_0= ruleReal ) ) ( (lv_timeUnit_10_0= ruleTimeUnit ) ) )
            	    // InternalRsamlText.g:1444:5: otherlv_8= 'start' ( (lv_startDate_9_0= ruleReal ) ) ( (lv_timeUnit_10_0= ruleTimeUnit ) )
            	    {
            	    otherlv_8=(Token)match(input,38,FOLLOW_14); 

            	    					newLeafNode(otherlv_8, grammarAccess.getActionAccess().getStartKeyword_3_2_0());
            	    				
            	    // InternalRsamlText.g:1448:5: ( (lv_startDate_9_0= ruleReal ) )
            	    // InternalRsamlText.g:1449:6: (lv_startDate_9_0= ruleReal )
            	    {
            	    // InternalRsamlText.g:1449:6: (lv_startDate_9_0= ruleReal )
            	    // InternalRsamlText.g:1450:7: lv_startDate_9_0= ruleReal
            	    {

            	    							newCompositeNode(grammarAccess.getActionAccess().getStartDateRealParserRuleCall_3_2_1_0());
            	    						
            	    pushFollow(FOLLOW_11);
            	    lv_startDate_9_0=ruleReal();

            	    state._fsp--;


            	    							if (current==null) {
            	    								current = createModelElementForParent(grammarAccess.getActionRule());
            	    							}
            	    							set(
            	    								current,
            	    								"startDate",
            	    								lv_startDate_9_0,
            	    								"org.rsaml.text.RsamlText.Real");
            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }

            	    // InternalRsamlText.g:1467:5: ( (lv_timeUnit_10_0= ruleTimeUnit ) )
            	    // InternalRsamlText.g:1468:6: (lv_timeUnit_10_0= ruleTimeUnit )
            	    {
            	    // InternalRsamlText.g:1468:6: (lv_timeUnit_10_0= ruleTimeUnit )
            	    // InternalRsamlText.g:1469:7: lv_timeUnit_10_0= ruleTimeUnit
            	    {

            	    							newCompositeNode(grammarAccess.getActionAccess().getTimeUnitTimeUnitEnumRuleCall_3_2_2_0());
            	    						
            	    pushFollow(FOLLOW_22);
            	    lv_timeUnit_10_0=ruleTimeUnit();

            	    state._fsp--;


            	    							if (current==null) {
            	    								current = createModelElementForParent(grammarAccess.getActionRule());
            	    							}
            	    							set(
            	    								current,
            	    								"timeUnit",
            	    								lv_timeUnit_10_0,
            	    								"org.rsaml.text.RsamlText.TimeUnit");
            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;

            	default :
            	    break loop14;
                }
            } while (true);

            otherlv_11=(Token)match(input,17,FOLLOW_2); 

            			newLeafNode(otherlv_11, grammarAccess.getActionAccess().getRightCurlyBracketKeyword_4());
            		

            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "ruleAction"


    // $ANTLR start "entryRulePort"
    // InternalRsamlText.g:1496:1: entryRulePort returns [EObject current=null] : iv_rulePort= rulePort EOF ;
    public final EObject entryRulePort() throws RecognitionException {
        EObject current = null;

        EObject iv_rulePort = null;


        try {
            // InternalRsamlText.g:1496:45: (iv_rulePort= rulePort EOF )
            // InternalRsamlText.g:1497:2: iv_rulePort= rulePort EOF
            {
             newCompositeNode(grammarAccess.getPortRule()); 
            pushFollow(FOLLOW_1);
            iv_rulePort=rulePort();

            state._fsp--;

             current =iv_rulePort; 
            match(input,EOF,FOLLOW_2); 

            }

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "entryRulePort"


    // $ANTLR start "rulePort"
    // InternalRsamlText.g:1503:1: rulePort returns [EObject current=null] : ( ( ( () otherlv_1= 'input' ) | ( () otherlv_3= 'output' ) ) ( (lv_name_4_0= ruleName ) )? otherlv_5= '{' (this_Described_6= ruleDescribed[$current] | (otherlv_7= 'dataType' ( (lv_dataType_8_0= ruleDataType ) ) ) | (otherlv_9= 'messageType' ( (lv_messageType_10_0= RULE_STRING ) ) ) | (otherlv_11= 'topic' ( (lv_topic_12_0= RULE_STRING ) ) ) )* otherlv_13= '}' ) ;
    public final EObject rulePort() throws RecognitionException {
        EObject current = null;

        Token otherlv_1=null;
        Token otherlv_3=null;
        Token otherlv_5=null;
        Token otherlv_7=null;
        Token otherlv_9=null;
        Token lv_messageType_10_0=null;
        Token otherlv_11=null;
        Token lv_topic_12_0=null;
        Token otherlv_13=null;
        AntlrDatatypeRuleToken lv_name_4_0 = null;

        EObject this_Described_6 = null;

        Enumerator lv_dataType_8_0 = null;



        	enterRule();

        try {
            // InternalRsamlText.g:1509:2: ( ( ( ( () otherlv_1= 'input' ) | ( () otherlv_3= 'output' ) ) ( (lv_name_4_0= ruleName ) )? otherlv_5= '{' (this_Described_6= ruleDescribed[$current] | (otherlv_7= 'dataType' ( (lv_dataType_8_0= ruleDataType ) ) ) | (otherlv_9= 'messageType' ( (lv_messageType_10_0= RULE_STRING ) ) ) | (otherlv_11= 'topic' ( (lv_topic_12_0= RULE_STRING ) ) ) )* otherlv_13= '}' ) )
            // InternalRsamlText.g:1510:2: ( ( ( () otherlv_1= 'input' ) | ( () otherlv_3= 'output' ) ) ( (lv_name_4_0= ruleName ) )? otherlv_5= '{' (this_Described_6= ruleDescribed[$current] | (otherlv_7= 'dataType' ( (lv_dataType_8_0= ruleDataType ) ) ) | (otherlv_9= 'messageType' ( (lv_messageType_10_0= RULE_STRING ) ) ) | (otherlv_11= 'topic' ( (lv_topic_12_0= RULE_STRING ) ) ) )* otherlv_13= '}' )
            {
            // InternalRsamlText.g:1510:2: ( ( ( () otherlv_1= 'input' ) | ( () otherlv_3= 'output' ) ) ( (lv_name_4_0= ruleName ) )? otherlv_5= '{' (this_Described_6= ruleDescribed[$current] | (otherlv_7= 'dataType' ( (lv_dataType_8_0= ruleDataType ) ) ) | (otherlv_9= 'messageType' ( (lv_messageType_10_0= RULE_STRING ) ) ) | (otherlv_11= 'topic' ( (lv_topic_12_0= RULE_STRING ) ) ) )* otherlv_13= '}' )
            // InternalRsamlText.g:1511:3: ( ( () otherlv_1= 'input' ) | ( () otherlv_3= 'output' ) ) ( (lv_name_4_0= ruleName ) )? otherlv_5= '{' (this_Described_6= ruleDescribed[$current] | (otherlv_7= 'dataType' ( (lv_dataType_8_0= ruleDataType ) ) ) | (otherlv_9= 'messageType' ( (lv_messageType_10_0= RULE_STRING ) ) ) | (otherlv_11= 'topic' ( (lv_topic_12_0= RULE_STRING ) ) ) )* otherlv_13= '}'
            {
            // InternalRsamlText.g:1511:3: ( ( () otherlv_1= 'input' ) | ( () otherlv_3= 'output' ) )
            int alt15=2;
            int LA15_0 = input.LA(1);

            if ( (LA15_0==39) ) {
                alt15=1;
            }
            else if ( (LA15_0==40) ) {
                alt15=2;
            }
            else {
                NoViableAltException nvae =
                    new NoViableAltException("", 15, 0, input);

                throw nvae;
            }
            switch (alt15) {
                case 1 :
                    // InternalRsamlText.g:1512:4: ( () otherlv_1= 'input' )
                    {
                    // InternalRsamlText.g:1512:4: ( () otherlv_1= 'input' )
                    // InternalRsamlText.g:1513:5: () otherlv_1= 'input'
                    {
                    // InternalRsamlText.g:1513:5: ()
                    // InternalRsamlText.g:1514:6: 
                    {

                    						current = forceCreateModelElement(
                    							grammarAccess.getPortAccess().getEntryPortAction_0_0_0(),
                    							current);
                    					

                    }

                    otherlv_1=(Token)match(input,39,FOLLOW_3); 

                    					newLeafNode(otherlv_1, grammarAccess.getPortAccess().getInputKeyword_0_0_1());
                    				

                    }


                    }
                    break;
                case 2 :
                    // InternalRsamlText.g:1526:4: ( () otherlv_3= 'output' )
                    {
                    // InternalRsamlText.g:1526:4: ( () otherlv_3= 'output' )
                    // InternalRsamlText.g:1527:5: () otherlv_3= 'output'
                    {
                    // InternalRsamlText.g:1527:5: ()
                    // InternalRsamlText.g:1528:6: 
                    {

                    						current = forceCreateModelElement(
                    							grammarAccess.getPortAccess().getOutputPortAction_0_1_0(),
                    							current);
                    					

                    }

                    otherlv_3=(Token)match(input,40,FOLLOW_3); 

                    					newLeafNode(otherlv_3, grammarAccess.getPortAccess().getOutputKeyword_0_1_1());
                    				

                    }


                    }
                    break;

            }

            // InternalRsamlText.g:1540:3: ( (lv_name_4_0= ruleName ) )?
            int alt16=2;
            int LA16_0 = input.LA(1);

            if ( ((LA16_0>=RULE_STRING && LA16_0<=RULE_ID)||LA16_0==11||(LA16_0>=13 && LA16_0<=16)||(LA16_0>=18 && LA16_0<=29)||(LA16_0>=31 && LA16_0<=44)||(LA16_0>=46 && LA16_0<=80)||(LA16_0>=82 && LA16_0<=118)) ) {
                alt16=1;
            }
            switch (alt16) {
                case 1 :
                    // InternalRsamlText.g:1541:4: (lv_name_4_0= ruleName )
                    {
                    // InternalRsamlText.g:1541:4: (lv_name_4_0= ruleName )
                    // InternalRsamlText.g:1542:5: lv_name_4_0= ruleName
                    {

                    					newCompositeNode(grammarAccess.getPortAccess().getNameNameParserRuleCall_1_0());
                    				
                    pushFollow(FOLLOW_4);
                    lv_name_4_0=ruleName();

                    state._fsp--;


                    					if (current==null) {
                    						current = createModelElementForParent(grammarAccess.getPortRule());
                    					}
                    					set(
                    						current,
                    						"name",
                    						lv_name_4_0,
                    						"org.rsaml.text.RsamlText.Name");
                    					afterParserOrEnumRuleCall();
                    				

                    }


                    }
                    break;

            }

            otherlv_5=(Token)match(input,12,FOLLOW_23); 

            			newLeafNode(otherlv_5, grammarAccess.getPortAccess().getLeftCurlyBracketKeyword_2());
            		
            // InternalRsamlText.g:1563:3: (this_Described_6= ruleDescribed[$current] | (otherlv_7= 'dataType' ( (lv_dataType_8_0= ruleDataType ) ) ) | (otherlv_9= 'messageType' ( (lv_messageType_10_0= RULE_STRING ) ) ) | (otherlv_11= 'topic' ( (lv_topic_12_0= RULE_STRING ) ) ) )*
            loop17:
            do {
                int alt17=5;
                switch ( input.LA(1) ) {
                case 18:
                    {
                    alt17=1;
                    }
                    break;
                case 41:
                    {
                    alt17=2;
                    }
                    break;
                case 42:
                    {
                    alt17=3;
                    }
                    break;
                case 43:
                    {
                    alt17=4;
                    }
                    break;

                }

                switch (alt17) {
            	case 1 :
            	    // InternalRsamlText.g:1564:4: this_Described_6= ruleDescribed[$current]
            	    {

            	    				if (current==null) {
            	    					current = createModelElement(grammarAccess.getPortRule());
            	    				}
            	    				newCompositeNode(grammarAccess.getPortAccess().getDescribedParserRuleCall_3_0());
            	    			
            	    pushFollow(FOLLOW_23);
            	    this_Described_6=ruleDescribed(current);

            	    state._fsp--;


            	    				current = this_Described_6;
            	    				afterParserOrEnumRuleCall();
            	    			

            	    }
            	    break;
            	case 2 :
            	    // InternalRsamlText.g:1576:4: (otherlv_7= 'dataType' ( (lv_dataType_8_0= ruleDataType ) ) )
            	    {
            	    // InternalRsamlText.g:1576:4: (otherlv_7= 'dataType' ( (lv_dataType_8_0= ruleDataType ) ) )
            	    // InternalRsamlText.g:1577:5: otherlv_7= 'dataType' ( (lv_dataType_8_0= ruleDataType ) )
            	    {
            	    otherlv_7=(Token)match(input,41,FOLLOW_24); 

            	    					newLeafNode(otherlv_7, grammarAccess.getPortAccess().getDataTypeKeyword_3_1_0());
            	    				
            	    // InternalRsamlText.g:1581:5: ( (lv_dataType_8_0= ruleDataType ) )
            	    // InternalRsamlText.g:1582:6: (lv_dataType_8_0= ruleDataType )
            	    {
            	    // InternalRsamlText.g:1582:6: (lv_dataType_8_0= ruleDataType )
            	    // InternalRsamlText.g:1583:7: lv_dataType_8_0= ruleDataType
            	    {

            	    							newCompositeNode(grammarAccess.getPortAccess().getDataTypeDataTypeEnumRuleCall_3_1_1_0());
            	    						
            	    pushFollow(FOLLOW_23);
            	    lv_dataType_8_0=ruleDataType();

            	    state._fsp--;


            	    							if (current==null) {
            	    								current = createModelElementForParent(grammarAccess.getPortRule());
            	    							}
            	    							set(
            	    								current,
            	    								"dataType",
            	    								lv_dataType_8_0,
            	    								"org.rsaml.text.RsamlText.DataType");
            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;
            	case 3 :
            	    // InternalRsamlText.g:1602:4: (otherlv_9= 'messageType' ( (lv_messageType_10_0= RULE_STRING ) ) )
            	    {
            	    // InternalRsamlText.g:1602:4: (otherlv_9= 'messageType' ( (lv_messageType_10_0= RULE_STRING ) ) )
            	    // InternalRsamlText.g:1603:5: otherlv_9= 'messageType' ( (lv_messageType_10_0= RULE_STRING ) )
            	    {
            	    otherlv_9=(Token)match(input,42,FOLLOW_10); 

            	    					newLeafNode(otherlv_9, grammarAccess.getPortAccess().getMessageTypeKeyword_3_2_0());
            	    				
            	    // InternalRsamlText.g:1607:5: ( (lv_messageType_10_0= RULE_STRING ) )
            	    // InternalRsamlText.g:1608:6: (lv_messageType_10_0= RULE_STRING )
            	    {
            	    // InternalRsamlText.g:1608:6: (lv_messageType_10_0= RULE_STRING )
            	    // InternalRsamlText.g:1609:7: lv_messageType_10_0= RULE_STRING
            	    {
            	    lv_messageType_10_0=(Token)match(input,RULE_STRING,FOLLOW_23); 

            	    							newLeafNode(lv_messageType_10_0, grammarAccess.getPortAccess().getMessageTypeSTRINGTerminalRuleCall_3_2_1_0());
            	    						

            	    							if (current==null) {
            	    								current = createModelElement(grammarAccess.getPortRule());
            	    							}
            	    							setWithLastConsumed(
            	    								current,
            	    								"messageType",
            	    								lv_messageType_10_0,
            	    								"org.rsaml.text.RsamlText.STRING");
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;
            	case 4 :
            	    // InternalRsamlText.g:1627:4: (otherlv_11= 'topic' ( (lv_topic_12_0= RULE_STRING ) ) )
            	    {
            	    // InternalRsamlText.g:1627:4: (otherlv_11= 'topic' ( (lv_topic_12_0= RULE_STRING ) ) )
            	    // InternalRsamlText.g:1628:5: otherlv_11= 'topic' ( (lv_topic_12_0= RULE_STRING ) )
            	    {
            	    otherlv_11=(Token)match(input,43,FOLLOW_10); 

            	    					newLeafNode(otherlv_11, grammarAccess.getPortAccess().getTopicKeyword_3_3_0());
            	    				
            	    // InternalRsamlText.g:1632:5: ( (lv_topic_12_0= RULE_STRING ) )
            	    // InternalRsamlText.g:1633:6: (lv_topic_12_0= RULE_STRING )
            	    {
            	    // InternalRsamlText.g:1633:6: (lv_topic_12_0= RULE_STRING )
            	    // InternalRsamlText.g:1634:7: lv_topic_12_0= RULE_STRING
            	    {
            	    lv_topic_12_0=(Token)match(input,RULE_STRING,FOLLOW_23); 

            	    							newLeafNode(lv_topic_12_0, grammarAccess.getPortAccess().getTopicSTRINGTerminalRuleCall_3_3_1_0());
            	    						

            	    							if (current==null) {
            	    								current = createModelElement(grammarAccess.getPortRule());
            	    							}
            	    							setWithLastConsumed(
            	    								current,
            	    								"topic",
            	    								lv_topic_12_0,
            	    								"org.rsaml.text.RsamlText.STRING");
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;

            	default :
            	    break loop17;
                }
            } while (true);

            otherlv_13=(Token)match(input,17,FOLLOW_2); 

            			newLeafNode(otherlv_13, grammarAccess.getPortAccess().getRightCurlyBracketKeyword_4());
            		

            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "rulePort"


    // $ANTLR start "entryRuleConnection"
    // InternalRsamlText.g:1660:1: entryRuleConnection returns [EObject current=null] : iv_ruleConnection= ruleConnection EOF ;
    public final EObject entryRuleConnection() throws RecognitionException {
        EObject current = null;

        EObject iv_ruleConnection = null;


        try {
            // InternalRsamlText.g:1660:51: (iv_ruleConnection= ruleConnection EOF )
            // InternalRsamlText.g:1661:2: iv_ruleConnection= ruleConnection EOF
            {
             newCompositeNode(grammarAccess.getConnectionRule()); 
            pushFollow(FOLLOW_1);
            iv_ruleConnection=ruleConnection();

            state._fsp--;

             current =iv_ruleConnection; 
            match(input,EOF,FOLLOW_2); 

            }

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "entryRuleConnection"


    // $ANTLR start "ruleConnection"
    // InternalRsamlText.g:1667:1: ruleConnection returns [EObject current=null] : ( () otherlv_1= 'connect' ( ( ruleQualifiedName ) )? otherlv_3= '->' ( ( ruleQualifiedName ) )? ) ;
    public final EObject ruleConnection() throws RecognitionException {
        EObject current = null;

        Token otherlv_1=null;
        Token otherlv_3=null;


        	enterRule();

        try {
            // InternalRsamlText.g:1673:2: ( ( () otherlv_1= 'connect' ( ( ruleQualifiedName ) )? otherlv_3= '->' ( ( ruleQualifiedName ) )? ) )
            // InternalRsamlText.g:1674:2: ( () otherlv_1= 'connect' ( ( ruleQualifiedName ) )? otherlv_3= '->' ( ( ruleQualifiedName ) )? )
            {
            // InternalRsamlText.g:1674:2: ( () otherlv_1= 'connect' ( ( ruleQualifiedName ) )? otherlv_3= '->' ( ( ruleQualifiedName ) )? )
            // InternalRsamlText.g:1675:3: () otherlv_1= 'connect' ( ( ruleQualifiedName ) )? otherlv_3= '->' ( ( ruleQualifiedName ) )?
            {
            // InternalRsamlText.g:1675:3: ()
            // InternalRsamlText.g:1676:4: 
            {

            				current = forceCreateModelElement(
            					grammarAccess.getConnectionAccess().getConnectionAction_0(),
            					current);
            			

            }

            otherlv_1=(Token)match(input,44,FOLLOW_25); 

            			newLeafNode(otherlv_1, grammarAccess.getConnectionAccess().getConnectKeyword_1());
            		
            // InternalRsamlText.g:1686:3: ( ( ruleQualifiedName ) )?
            int alt18=2;
            int LA18_0 = input.LA(1);

            if ( ((LA18_0>=RULE_STRING && LA18_0<=RULE_ID)) ) {
                alt18=1;
            }
            switch (alt18) {
                case 1 :
                    // InternalRsamlText.g:1687:4: ( ruleQualifiedName )
                    {
                    // InternalRsamlText.g:1687:4: ( ruleQualifiedName )
                    // InternalRsamlText.g:1688:5: ruleQualifiedName
                    {

                    					if (current==null) {
                    						current = createModelElement(grammarAccess.getConnectionRule());
                    					}
                    				

                    					newCompositeNode(grammarAccess.getConnectionAccess().getSourceOutputPortCrossReference_2_0());
                    				
                    pushFollow(FOLLOW_26);
                    ruleQualifiedName();

                    state._fsp--;


                    					afterParserOrEnumRuleCall();
                    				

                    }


                    }
                    break;

            }

            otherlv_3=(Token)match(input,45,FOLLOW_27); 

            			newLeafNode(otherlv_3, grammarAccess.getConnectionAccess().getHyphenMinusGreaterThanSignKeyword_3());
            		
            // InternalRsamlText.g:1706:3: ( ( ruleQualifiedName ) )?
            int alt19=2;
            int LA19_0 = input.LA(1);

            if ( ((LA19_0>=RULE_STRING && LA19_0<=RULE_ID)) ) {
                alt19=1;
            }
            switch (alt19) {
                case 1 :
                    // InternalRsamlText.g:1707:4: ( ruleQualifiedName )
                    {
                    // InternalRsamlText.g:1707:4: ( ruleQualifiedName )
                    // InternalRsamlText.g:1708:5: ruleQualifiedName
                    {

                    					if (current==null) {
                    						current = createModelElement(grammarAccess.getConnectionRule());
                    					}
                    				

                    					newCompositeNode(grammarAccess.getConnectionAccess().getTargetEntryPortCrossReference_4_0());
                    				
                    pushFollow(FOLLOW_2);
                    ruleQualifiedName();

                    state._fsp--;


                    					afterParserOrEnumRuleCall();
                    				

                    }


                    }
                    break;

            }


            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "ruleConnection"


    // $ANTLR start "entryRuleInhibitor"
    // InternalRsamlText.g:1726:1: entryRuleInhibitor returns [EObject current=null] : iv_ruleInhibitor= ruleInhibitor EOF ;
    public final EObject entryRuleInhibitor() throws RecognitionException {
        EObject current = null;

        EObject iv_ruleInhibitor = null;


        try {
            // InternalRsamlText.g:1726:50: (iv_ruleInhibitor= ruleInhibitor EOF )
            // InternalRsamlText.g:1727:2: iv_ruleInhibitor= ruleInhibitor EOF
            {
             newCompositeNode(grammarAccess.getInhibitorRule()); 
            pushFollow(FOLLOW_1);
            iv_ruleInhibitor=ruleInhibitor();

            state._fsp--;

             current =iv_ruleInhibitor; 
            match(input,EOF,FOLLOW_2); 

            }

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "entryRuleInhibitor"


    // $ANTLR start "ruleInhibitor"
    // InternalRsamlText.g:1733:1: ruleInhibitor returns [EObject current=null] : ( () otherlv_1= 'inhibitor' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'trigger' ( ( ruleQualifiedName ) ) ) | (otherlv_7= 'target' ( ( ruleQualifiedName ) ) ) | (otherlv_9= 'duration' ( (lv_duration_10_0= ruleReal ) ) ( (lv_timeUnit_11_0= ruleTimeUnit ) ) ) | this_Unit_12= ruleUnit[$current] )* otherlv_13= '}' ) ;
    public final EObject ruleInhibitor() throws RecognitionException {
        EObject current = null;

        Token otherlv_1=null;
        Token otherlv_3=null;
        Token otherlv_5=null;
        Token otherlv_7=null;
        Token otherlv_9=null;
        Token otherlv_13=null;
        AntlrDatatypeRuleToken lv_name_2_0 = null;

        EObject this_Described_4 = null;

        AntlrDatatypeRuleToken lv_duration_10_0 = null;

        Enumerator lv_timeUnit_11_0 = null;

        EObject this_Unit_12 = null;



        	enterRule();

        try {
            // InternalRsamlText.g:1739:2: ( ( () otherlv_1= 'inhibitor' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'trigger' ( ( ruleQualifiedName ) ) ) | (otherlv_7= 'target' ( ( ruleQualifiedName ) ) ) | (otherlv_9= 'duration' ( (lv_duration_10_0= ruleReal ) ) ( (lv_timeUnit_11_0= ruleTimeUnit ) ) ) | this_Unit_12= ruleUnit[$current] )* otherlv_13= '}' ) )
            // InternalRsamlText.g:1740:2: ( () otherlv_1= 'inhibitor' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'trigger' ( ( ruleQualifiedName ) ) ) | (otherlv_7= 'target' ( ( ruleQualifiedName ) ) ) | (otherlv_9= 'duration' ( (lv_duration_10_0= ruleReal ) ) ( (lv_timeUnit_11_0= ruleTimeUnit ) ) ) | this_Unit_12= ruleUnit[$current] )* otherlv_13= '}' )
            {
            // InternalRsamlText.g:1740:2: ( () otherlv_1= 'inhibitor' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'trigger' ( ( ruleQualifiedName ) ) ) | (otherlv_7= 'target' ( ( ruleQualifiedName ) ) ) | (otherlv_9= 'duration' ( (lv_duration_10_0= ruleReal ) ) ( (lv_timeUnit_11_0= ruleTimeUnit ) ) ) | this_Unit_12= ruleUnit[$current] )* otherlv_13= '}' )
            // InternalRsamlText.g:1741:3: () otherlv_1= 'inhibitor' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'trigger' ( ( ruleQualifiedName ) ) ) | (otherlv_7= 'target' ( ( ruleQualifiedName ) ) ) | (otherlv_9= 'duration' ( (lv_duration_10_0= ruleReal ) ) ( (lv_timeUnit_11_0= ruleTimeUnit ) ) ) | this_Unit_12= ruleUnit[$current] )* otherlv_13= '}'
            {
            // InternalRsamlText.g:1741:3: ()
            // InternalRsamlText.g:1742:4: 
            {

            				current = forceCreateModelElement(
            					grammarAccess.getInhibitorAccess().getInhibitorAction_0(),
            					current);
            			

            }

            otherlv_1=(Token)match(input,46,FOLLOW_3); 

            			newLeafNode(otherlv_1, grammarAccess.getInhibitorAccess().getInhibitorKeyword_1());
            		
            // InternalRsamlText.g:1752:3: ( (lv_name_2_0= ruleName ) )?
            int alt20=2;
            int LA20_0 = input.LA(1);

            if ( ((LA20_0>=RULE_STRING && LA20_0<=RULE_ID)||LA20_0==11||(LA20_0>=13 && LA20_0<=16)||(LA20_0>=18 && LA20_0<=29)||(LA20_0>=31 && LA20_0<=44)||(LA20_0>=46 && LA20_0<=80)||(LA20_0>=82 && LA20_0<=118)) ) {
                alt20=1;
            }
            switch (alt20) {
                case 1 :
                    // InternalRsamlText.g:1753:4: (lv_name_2_0= ruleName )
                    {
                    // InternalRsamlText.g:1753:4: (lv_name_2_0= ruleName )
                    // InternalRsamlText.g:1754:5: lv_name_2_0= ruleName
                    {

                    					newCompositeNode(grammarAccess.getInhibitorAccess().getNameNameParserRuleCall_2_0());
                    				
                    pushFollow(FOLLOW_4);
                    lv_name_2_0=ruleName();

                    state._fsp--;


                    					if (current==null) {
                    						current = createModelElementForParent(grammarAccess.getInhibitorRule());
                    					}
                    					set(
                    						current,
                    						"name",
                    						lv_name_2_0,
                    						"org.rsaml.text.RsamlText.Name");
                    					afterParserOrEnumRuleCall();
                    				

                    }


                    }
                    break;

            }

            otherlv_3=(Token)match(input,12,FOLLOW_28); 

            			newLeafNode(otherlv_3, grammarAccess.getInhibitorAccess().getLeftCurlyBracketKeyword_3());
            		
            // InternalRsamlText.g:1775:3: (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'trigger' ( ( ruleQualifiedName ) ) ) | (otherlv_7= 'target' ( ( ruleQualifiedName ) ) ) | (otherlv_9= 'duration' ( (lv_duration_10_0= ruleReal ) ) ( (lv_timeUnit_11_0= ruleTimeUnit ) ) ) | this_Unit_12= ruleUnit[$current] )*
            loop21:
            do {
                int alt21=6;
                switch ( input.LA(1) ) {
                case 18:
                    {
                    alt21=1;
                    }
                    break;
                case 47:
                    {
                    alt21=2;
                    }
                    break;
                case 48:
                    {
                    alt21=3;
                    }
                    break;
                case 49:
                    {
                    alt21=4;
                    }
                    break;
                case 19:
                    {
                    alt21=5;
                    }
                    break;

                }

                switch (alt21) {
            	case 1 :
            	    // InternalRsamlText.g:1776:4: this_Described_4= ruleDescribed[$current]
            	    {

            	    				if (current==null) {
            	    					current = createModelElement(grammarAccess.getInhibitorRule());
            	    				}
            	    				newCompositeNode(grammarAccess.getInhibitorAccess().getDescribedParserRuleCall_4_0());
            	    			
            	    pushFollow(FOLLOW_28);
            	    this_Described_4=ruleDescribed(current);

            	    state._fsp--;


            	    				current = this_Described_4;
            	    				afterParserOrEnumRuleCall();
            	    			

            	    }
            	    break;
            	case 2 :
            	    // InternalRsamlText.g:1788:4: (otherlv_5= 'trigger' ( ( ruleQualifiedName ) ) )
            	    {
            	    // InternalRsamlText.g:1788:4: (otherlv_5= 'trigger' ( ( ruleQualifiedName ) ) )
            	    // InternalRsamlText.g:1789:5: otherlv_5= 'trigger' ( ( ruleQualifiedName ) )
            	    {
            	    otherlv_5=(Token)match(input,47,FOLLOW_17); 

            	    					newLeafNode(otherlv_5, grammarAccess.getInhibitorAccess().getTriggerKeyword_4_1_0());
            	    				
            	    // InternalRsamlText.g:1793:5: ( ( ruleQualifiedName ) )
            	    // InternalRsamlText.g:1794:6: ( ruleQualifiedName )
            	    {
            	    // InternalRsamlText.g:1794:6: ( ruleQualifiedName )
            	    // InternalRsamlText.g:1795:7: ruleQualifiedName
            	    {

            	    							if (current==null) {
            	    								current = createModelElement(grammarAccess.getInhibitorRule());
            	    							}
            	    						

            	    							newCompositeNode(grammarAccess.getInhibitorAccess().getTriggerOutputPortCrossReference_4_1_1_0());
            	    						
            	    pushFollow(FOLLOW_28);
            	    ruleQualifiedName();

            	    state._fsp--;


            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;
            	case 3 :
            	    // InternalRsamlText.g:1811:4: (otherlv_7= 'target' ( ( ruleQualifiedName ) ) )
            	    {
            	    // InternalRsamlText.g:1811:4: (otherlv_7= 'target' ( ( ruleQualifiedName ) ) )
            	    // InternalRsamlText.g:1812:5: otherlv_7= 'target' ( ( ruleQualifiedName ) )
            	    {
            	    otherlv_7=(Token)match(input,48,FOLLOW_17); 

            	    					newLeafNode(otherlv_7, grammarAccess.getInhibitorAccess().getTargetKeyword_4_2_0());
            	    				
            	    // InternalRsamlText.g:1816:5: ( ( ruleQualifiedName ) )
            	    // InternalRsamlText.g:1817:6: ( ruleQualifiedName )
            	    {
            	    // InternalRsamlText.g:1817:6: ( ruleQualifiedName )
            	    // InternalRsamlText.g:1818:7: ruleQualifiedName
            	    {

            	    							if (current==null) {
            	    								current = createModelElement(grammarAccess.getInhibitorRule());
            	    							}
            	    						

            	    							newCompositeNode(grammarAccess.getInhibitorAccess().getTargetOutputPortCrossReference_4_2_1_0());
            	    						
            	    pushFollow(FOLLOW_28);
            	    ruleQualifiedName();

            	    state._fsp--;


            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;
            	case 4 :
            	    // InternalRsamlText.g:1834:4: (otherlv_9= 'duration' ( (lv_duration_10_0= ruleReal ) ) ( (lv_timeUnit_11_0= ruleTimeUnit ) ) )
            	    {
            	    // InternalRsamlText.g:1834:4: (otherlv_9= 'duration' ( (lv_duration_10_0= ruleReal ) ) ( (lv_timeUnit_11_0= ruleTimeUnit ) ) )
            	    // InternalRsamlText.g:1835:5: otherlv_9= 'duration' ( (lv_duration_10_0= ruleReal ) ) ( (lv_timeUnit_11_0= ruleTimeUnit ) )
            	    {
            	    otherlv_9=(Token)match(input,49,FOLLOW_14); 

            	    					newLeafNode(otherlv_9, grammarAccess.getInhibitorAccess().getDurationKeyword_4_3_0());
            	    				
            	    // InternalRsamlText.g:1839:5: ( (lv_duration_10_0= ruleReal ) )
            	    // InternalRsamlText.g:1840:6: (lv_duration_10_0= ruleReal )
            	    {
            	    // InternalRsamlText.g:1840:6: (lv_duration_10_0= ruleReal )
            	    // InternalRsamlText.g:1841:7: lv_duration_10_0= ruleReal
            	    {

            	    							newCompositeNode(grammarAccess.getInhibitorAccess().getDurationRealParserRuleCall_4_3_1_0());
            	    						
            	    pushFollow(FOLLOW_11);
            	    lv_duration_10_0=ruleReal();

            	    state._fsp--;


            	    							if (current==null) {
            	    								current = createModelElementForParent(grammarAccess.getInhibitorRule());
            	    							}
            	    							set(
            	    								current,
            	    								"duration",
            	    								lv_duration_10_0,
            	    								"org.rsaml.text.RsamlText.Real");
            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }

            	    // InternalRsamlText.g:1858:5: ( (lv_timeUnit_11_0= ruleTimeUnit ) )
            	    // InternalRsamlText.g:1859:6: (lv_timeUnit_11_0= ruleTimeUnit )
            	    {
            	    // InternalRsamlText.g:1859:6: (lv_timeUnit_11_0= ruleTimeUnit )
            	    // InternalRsamlText.g:1860:7: lv_timeUnit_11_0= ruleTimeUnit
            	    {

            	    							newCompositeNode(grammarAccess.getInhibitorAccess().getTimeUnitTimeUnitEnumRuleCall_4_3_2_0());
            	    						
            	    pushFollow(FOLLOW_28);
            	    lv_timeUnit_11_0=ruleTimeUnit();

            	    state._fsp--;


            	    							if (current==null) {
            	    								current = createModelElementForParent(grammarAccess.getInhibitorRule());
            	    							}
            	    							set(
            	    								current,
            	    								"timeUnit",
            	    								lv_timeUnit_11_0,
            	    								"org.rsaml.text.RsamlText.TimeUnit");
            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;
            	case 5 :
            	    // InternalRsamlText.g:1879:4: this_Unit_12= ruleUnit[$current]
            	    {

            	    				if (current==null) {
            	    					current = createModelElement(grammarAccess.getInhibitorRule());
            	    				}
            	    				newCompositeNode(grammarAccess.getInhibitorAccess().getUnitParserRuleCall_4_4());
            	    			
            	    pushFollow(FOLLOW_28);
            	    this_Unit_12=ruleUnit(current);

            	    state._fsp--;


            	    				current = this_Unit_12;
            	    				afterParserOrEnumRuleCall();
            	    			

            	    }
            	    break;

            	default :
            	    break loop21;
                }
            } while (true);

            otherlv_13=(Token)match(input,17,FOLLOW_2); 

            			newLeafNode(otherlv_13, grammarAccess.getInhibitorAccess().getRightCurlyBracketKeyword_5());
            		

            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "ruleInhibitor"


    // $ANTLR start "entryRuleSuppressor"
    // InternalRsamlText.g:1899:1: entryRuleSuppressor returns [EObject current=null] : iv_ruleSuppressor= ruleSuppressor EOF ;
    public final EObject entryRuleSuppressor() throws RecognitionException {
        EObject current = null;

        EObject iv_ruleSuppressor = null;


        try {
            // InternalRsamlText.g:1899:51: (iv_ruleSuppressor= ruleSuppressor EOF )
            // InternalRsamlText.g:1900:2: iv_ruleSuppressor= ruleSuppressor EOF
            {
             newCompositeNode(grammarAccess.getSuppressorRule()); 
            pushFollow(FOLLOW_1);
            iv_ruleSuppressor=ruleSuppressor();

            state._fsp--;

             current =iv_ruleSuppressor; 
            match(input,EOF,FOLLOW_2); 

            }

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "entryRuleSuppressor"


    // $ANTLR start "ruleSuppressor"
    // InternalRsamlText.g:1906:1: ruleSuppressor returns [EObject current=null] : ( () otherlv_1= 'suppressor' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'trigger' ( ( ruleQualifiedName ) ) ) | (otherlv_7= 'target' ( ( ruleQualifiedName ) ) ) | (otherlv_9= 'duration' ( (lv_duration_10_0= ruleReal ) ) ( (lv_timeUnit_11_0= ruleTimeUnit ) ) ) | this_Unit_12= ruleUnit[$current] )* otherlv_13= '}' ) ;
    public final EObject ruleSuppressor() throws RecognitionException {
        EObject current = null;

        Token otherlv_1=null;
        Token otherlv_3=null;
        Token otherlv_5=null;
        Token otherlv_7=null;
        Token otherlv_9=null;
        Token otherlv_13=null;
        AntlrDatatypeRuleToken lv_name_2_0 = null;

        EObject this_Described_4 = null;

        AntlrDatatypeRuleToken lv_duration_10_0 = null;

        Enumerator lv_timeUnit_11_0 = null;

        EObject this_Unit_12 = null;



        	enterRule();

        try {
            // InternalRsamlText.g:1912:2: ( ( () otherlv_1= 'suppressor' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'trigger' ( ( ruleQualifiedName ) ) ) | (otherlv_7= 'target' ( ( ruleQualifiedName ) ) ) | (otherlv_9= 'duration' ( (lv_duration_10_0= ruleReal ) ) ( (lv_timeUnit_11_0= ruleTimeUnit ) ) ) | this_Unit_12= ruleUnit[$current] )* otherlv_13= '}' ) )
            // InternalRsamlText.g:1913:2: ( () otherlv_1= 'suppressor' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'trigger' ( ( ruleQualifiedName ) ) ) | (otherlv_7= 'target' ( ( ruleQualifiedName ) ) ) | (otherlv_9= 'duration' ( (lv_duration_10_0= ruleReal ) ) ( (lv_timeUnit_11_0= ruleTimeUnit ) ) ) | this_Unit_12= ruleUnit[$current] )* otherlv_13= '}' )
            {
            // InternalRsamlText.g:1913:2: ( () otherlv_1= 'suppressor' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'trigger' ( ( ruleQualifiedName ) ) ) | (otherlv_7= 'target' ( ( ruleQualifiedName ) ) ) | (otherlv_9= 'duration' ( (lv_duration_10_0= ruleReal ) ) ( (lv_timeUnit_11_0= ruleTimeUnit ) ) ) | this_Unit_12= ruleUnit[$current] )* otherlv_13= '}' )
            // InternalRsamlText.g:1914:3: () otherlv_1= 'suppressor' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'trigger' ( ( ruleQualifiedName ) ) ) | (otherlv_7= 'target' ( ( ruleQualifiedName ) ) ) | (otherlv_9= 'duration' ( (lv_duration_10_0= ruleReal ) ) ( (lv_timeUnit_11_0= ruleTimeUnit ) ) ) | this_Unit_12= ruleUnit[$current] )* otherlv_13= '}'
            {
            // InternalRsamlText.g:1914:3: ()
            // InternalRsamlText.g:1915:4: 
            {

            				current = forceCreateModelElement(
            					grammarAccess.getSuppressorAccess().getSuppressorAction_0(),
            					current);
            			

            }

            otherlv_1=(Token)match(input,50,FOLLOW_3); 

            			newLeafNode(otherlv_1, grammarAccess.getSuppressorAccess().getSuppressorKeyword_1());
            		
            // InternalRsamlText.g:1925:3: ( (lv_name_2_0= ruleName ) )?
            int alt22=2;
            int LA22_0 = input.LA(1);

            if ( ((LA22_0>=RULE_STRING && LA22_0<=RULE_ID)||LA22_0==11||(LA22_0>=13 && LA22_0<=16)||(LA22_0>=18 && LA22_0<=29)||(LA22_0>=31 && LA22_0<=44)||(LA22_0>=46 && LA22_0<=80)||(LA22_0>=82 && LA22_0<=118)) ) {
                alt22=1;
            }
            switch (alt22) {
                case 1 :
                    // InternalRsamlText.g:1926:4: (lv_name_2_0= ruleName )
                    {
                    // InternalRsamlText.g:1926:4: (lv_name_2_0= ruleName )
                    // InternalRsamlText.g:1927:5: lv_name_2_0= ruleName
                    {

                    					newCompositeNode(grammarAccess.getSuppressorAccess().getNameNameParserRuleCall_2_0());
                    				
                    pushFollow(FOLLOW_4);
                    lv_name_2_0=ruleName();

                    state._fsp--;


                    					if (current==null) {
                    						current = createModelElementForParent(grammarAccess.getSuppressorRule());
                    					}
                    					set(
                    						current,
                    						"name",
                    						lv_name_2_0,
                    						"org.rsaml.text.RsamlText.Name");
                    					afterParserOrEnumRuleCall();
                    				

                    }


                    }
                    break;

            }

            otherlv_3=(Token)match(input,12,FOLLOW_28); 

            			newLeafNode(otherlv_3, grammarAccess.getSuppressorAccess().getLeftCurlyBracketKeyword_3());
            		
            // InternalRsamlText.g:1948:3: (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'trigger' ( ( ruleQualifiedName ) ) ) | (otherlv_7= 'target' ( ( ruleQualifiedName ) ) ) | (otherlv_9= 'duration' ( (lv_duration_10_0= ruleReal ) ) ( (lv_timeUnit_11_0= ruleTimeUnit ) ) ) | this_Unit_12= ruleUnit[$current] )*
            loop23:
            do {
                int alt23=6;
                switch ( input.LA(1) ) {
                case 18:
                    {
                    alt23=1;
                    }
                    break;
                case 47:
                    {
                    alt23=2;
                    }
                    break;
                case 48:
                    {
                    alt23=3;
                    }
                    break;
                case 49:
                    {
                    alt23=4;
                    }
                    break;
                case 19:
                    {
                    alt23=5;
                    }
                    break;

                }

                switch (alt23) {
            	case 1 :
            	    // InternalRsamlText.g:1949:4: this_Described_4= ruleDescribed[$current]
            	    {

            	    				if (current==null) {
            	    					current = createModelElement(grammarAccess.getSuppressorRule());
            	    				}
            	    				newCompositeNode(grammarAccess.getSuppressorAccess().getDescribedParserRuleCall_4_0());
            	    			
            	    pushFollow(FOLLOW_28);
            	    this_Described_4=ruleDescribed(current);

            	    state._fsp--;


            	    				current = this_Described_4;
            	    				afterParserOrEnumRuleCall();
            	    			

            	    }
            	    break;
            	case 2 :
            	    // InternalRsamlText.g:1961:4: (otherlv_5= 'trigger' ( ( ruleQualifiedName ) ) )
            	    {
            	    // InternalRsamlText.g:1961:4: (otherlv_5= 'trigger' ( ( ruleQualifiedName ) ) )
            	    // InternalRsamlText.g:1962:5: otherlv_5= 'trigger' ( ( ruleQualifiedName ) )
            	    {
            	    otherlv_5=(Token)match(input,47,FOLLOW_17); 

            	    					newLeafNode(otherlv_5, grammarAccess.getSuppressorAccess().getTriggerKeyword_4_1_0());
            	    				
            	    // InternalRsamlText.g:1966:5: ( ( ruleQualifiedName ) )
            	    // InternalRsamlText.g:1967:6: ( ruleQualifiedName )
            	    {
            	    // InternalRsamlText.g:1967:6: ( ruleQualifiedName )
            	    // InternalRsamlText.g:1968:7: ruleQualifiedName
            	    {

            	    							if (current==null) {
            	    								current = createModelElement(grammarAccess.getSuppressorRule());
            	    							}
            	    						

            	    							newCompositeNode(grammarAccess.getSuppressorAccess().getTriggerOutputPortCrossReference_4_1_1_0());
            	    						
            	    pushFollow(FOLLOW_28);
            	    ruleQualifiedName();

            	    state._fsp--;


            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;
            	case 3 :
            	    // InternalRsamlText.g:1984:4: (otherlv_7= 'target' ( ( ruleQualifiedName ) ) )
            	    {
            	    // InternalRsamlText.g:1984:4: (otherlv_7= 'target' ( ( ruleQualifiedName ) ) )
            	    // InternalRsamlText.g:1985:5: otherlv_7= 'target' ( ( ruleQualifiedName ) )
            	    {
            	    otherlv_7=(Token)match(input,48,FOLLOW_17); 

            	    					newLeafNode(otherlv_7, grammarAccess.getSuppressorAccess().getTargetKeyword_4_2_0());
            	    				
            	    // InternalRsamlText.g:1989:5: ( ( ruleQualifiedName ) )
            	    // InternalRsamlText.g:1990:6: ( ruleQualifiedName )
            	    {
            	    // InternalRsamlText.g:1990:6: ( ruleQualifiedName )
            	    // InternalRsamlText.g:1991:7: ruleQualifiedName
            	    {

            	    							if (current==null) {
            	    								current = createModelElement(grammarAccess.getSuppressorRule());
            	    							}
            	    						

            	    							newCompositeNode(grammarAccess.getSuppressorAccess().getTargetEntryPortCrossReference_4_2_1_0());
            	    						
            	    pushFollow(FOLLOW_28);
            	    ruleQualifiedName();

            	    state._fsp--;


            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;
            	case 4 :
            	    // InternalRsamlText.g:2007:4: (otherlv_9= 'duration' ( (lv_duration_10_0= ruleReal ) ) ( (lv_timeUnit_11_0= ruleTimeUnit ) ) )
            	    {
            	    // InternalRsamlText.g:2007:4: (otherlv_9= 'duration' ( (lv_duration_10_0= ruleReal ) ) ( (lv_timeUnit_11_0= ruleTimeUnit ) ) )
            	    // InternalRsamlText.g:2008:5: otherlv_9= 'duration' ( (lv_duration_10_0= ruleReal ) ) ( (lv_timeUnit_11_0= ruleTimeUnit ) )
            	    {
            	    otherlv_9=(Token)match(input,49,FOLLOW_14); 

            	    					newLeafNode(otherlv_9, grammarAccess.getSuppressorAccess().getDurationKeyword_4_3_0());
            	    				
            	    // InternalRsamlText.g:2012:5: ( (lv_duration_10_0= ruleReal ) )
            	    // InternalRsamlText.g:2013:6: (lv_duration_10_0= ruleReal )
            	    {
            	    // InternalRsamlText.g:2013:6: (lv_duration_10_0= ruleReal )
            	    // InternalRsamlText.g:2014:7: lv_duration_10_0= ruleReal
            	    {

            	    							newCompositeNode(grammarAccess.getSuppressorAccess().getDurationRealParserRuleCall_4_3_1_0());
            	    						
            	    pushFollow(FOLLOW_11);
            	    lv_duration_10_0=ruleReal();

            	    state._fsp--;


            	    							if (current==null) {
            	    								current = createModelElementForParent(grammarAccess.getSuppressorRule());
            	    							}
            	    							set(
            	    								current,
            	    								"duration",
            	    								lv_duration_10_0,
            	    								"org.rsaml.text.RsamlText.Real");
            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }

            	    // InternalRsamlText.g:2031:5: ( (lv_timeUnit_11_0= ruleTimeUnit ) )
            	    // InternalRsamlText.g:2032:6: (lv_timeUnit_11_0= ruleTimeUnit )
            	    {
            	    // InternalRsamlText.g:2032:6: (lv_timeUnit_11_0= ruleTimeUnit )
            	    // InternalRsamlText.g:2033:7: lv_timeUnit_11_0= ruleTimeUnit
            	    {

            	    							newCompositeNode(grammarAccess.getSuppressorAccess().getTimeUnitTimeUnitEnumRuleCall_4_3_2_0());
            	    						
            	    pushFollow(FOLLOW_28);
            	    lv_timeUnit_11_0=ruleTimeUnit();

            	    state._fsp--;


            	    							if (current==null) {
            	    								current = createModelElementForParent(grammarAccess.getSuppressorRule());
            	    							}
            	    							set(
            	    								current,
            	    								"timeUnit",
            	    								lv_timeUnit_11_0,
            	    								"org.rsaml.text.RsamlText.TimeUnit");
            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;
            	case 5 :
            	    // InternalRsamlText.g:2052:4: this_Unit_12= ruleUnit[$current]
            	    {

            	    				if (current==null) {
            	    					current = createModelElement(grammarAccess.getSuppressorRule());
            	    				}
            	    				newCompositeNode(grammarAccess.getSuppressorAccess().getUnitParserRuleCall_4_4());
            	    			
            	    pushFollow(FOLLOW_28);
            	    this_Unit_12=ruleUnit(current);

            	    state._fsp--;


            	    				current = this_Unit_12;
            	    				afterParserOrEnumRuleCall();
            	    			

            	    }
            	    break;

            	default :
            	    break loop23;
                }
            } while (true);

            otherlv_13=(Token)match(input,17,FOLLOW_2); 

            			newLeafNode(otherlv_13, grammarAccess.getSuppressorAccess().getRightCurlyBracketKeyword_5());
            		

            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "ruleSuppressor"


    // $ANTLR start "entryRuleSensor"
    // InternalRsamlText.g:2072:1: entryRuleSensor returns [EObject current=null] : iv_ruleSensor= ruleSensor EOF ;
    public final EObject entryRuleSensor() throws RecognitionException {
        EObject current = null;

        EObject iv_ruleSensor = null;


        try {
            // InternalRsamlText.g:2072:47: (iv_ruleSensor= ruleSensor EOF )
            // InternalRsamlText.g:2073:2: iv_ruleSensor= ruleSensor EOF
            {
             newCompositeNode(grammarAccess.getSensorRule()); 
            pushFollow(FOLLOW_1);
            iv_ruleSensor=ruleSensor();

            state._fsp--;

             current =iv_ruleSensor; 
            match(input,EOF,FOLLOW_2); 

            }

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "entryRuleSensor"


    // $ANTLR start "ruleSensor"
    // InternalRsamlText.g:2079:1: ruleSensor returns [EObject current=null] : ( () otherlv_1= 'sensor' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'kind' ( (lv_kind_6_0= RULE_STRING ) ) ) | (otherlv_7= 'dataType' ( (lv_dataType_8_0= ruleDataType ) ) ) | (otherlv_9= 'period' ( (lv_period_10_0= ruleReal ) ) ( (lv_timeUnit_11_0= ruleTimeUnit ) ) ) | this_Unit_12= ruleUnit[$current] )* otherlv_13= '}' ) ;
    public final EObject ruleSensor() throws RecognitionException {
        EObject current = null;

        Token otherlv_1=null;
        Token otherlv_3=null;
        Token otherlv_5=null;
        Token lv_kind_6_0=null;
        Token otherlv_7=null;
        Token otherlv_9=null;
        Token otherlv_13=null;
        AntlrDatatypeRuleToken lv_name_2_0 = null;

        EObject this_Described_4 = null;

        Enumerator lv_dataType_8_0 = null;

        AntlrDatatypeRuleToken lv_period_10_0 = null;

        Enumerator lv_timeUnit_11_0 = null;

        EObject this_Unit_12 = null;



        	enterRule();

        try {
            // InternalRsamlText.g:2085:2: ( ( () otherlv_1= 'sensor' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'kind' ( (lv_kind_6_0= RULE_STRING ) ) ) | (otherlv_7= 'dataType' ( (lv_dataType_8_0= ruleDataType ) ) ) | (otherlv_9= 'period' ( (lv_period_10_0= ruleReal ) ) ( (lv_timeUnit_11_0= ruleTimeUnit ) ) ) | this_Unit_12= ruleUnit[$current] )* otherlv_13= '}' ) )
            // InternalRsamlText.g:2086:2: ( () otherlv_1= 'sensor' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'kind' ( (lv_kind_6_0= RULE_STRING ) ) ) | (otherlv_7= 'dataType' ( (lv_dataType_8_0= ruleDataType ) ) ) | (otherlv_9= 'period' ( (lv_period_10_0= ruleReal ) ) ( (lv_timeUnit_11_0= ruleTimeUnit ) ) ) | this_Unit_12= ruleUnit[$current] )* otherlv_13= '}' )
            {
            // InternalRsamlText.g:2086:2: ( () otherlv_1= 'sensor' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'kind' ( (lv_kind_6_0= RULE_STRING ) ) ) | (otherlv_7= 'dataType' ( (lv_dataType_8_0= ruleDataType ) ) ) | (otherlv_9= 'period' ( (lv_period_10_0= ruleReal ) ) ( (lv_timeUnit_11_0= ruleTimeUnit ) ) ) | this_Unit_12= ruleUnit[$current] )* otherlv_13= '}' )
            // InternalRsamlText.g:2087:3: () otherlv_1= 'sensor' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'kind' ( (lv_kind_6_0= RULE_STRING ) ) ) | (otherlv_7= 'dataType' ( (lv_dataType_8_0= ruleDataType ) ) ) | (otherlv_9= 'period' ( (lv_period_10_0= ruleReal ) ) ( (lv_timeUnit_11_0= ruleTimeUnit ) ) ) | this_Unit_12= ruleUnit[$current] )* otherlv_13= '}'
            {
            // InternalRsamlText.g:2087:3: ()
            // InternalRsamlText.g:2088:4: 
            {

            				current = forceCreateModelElement(
            					grammarAccess.getSensorAccess().getSensorAction_0(),
            					current);
            			

            }

            otherlv_1=(Token)match(input,51,FOLLOW_3); 

            			newLeafNode(otherlv_1, grammarAccess.getSensorAccess().getSensorKeyword_1());
            		
            // InternalRsamlText.g:2098:3: ( (lv_name_2_0= ruleName ) )?
            int alt24=2;
            int LA24_0 = input.LA(1);

            if ( ((LA24_0>=RULE_STRING && LA24_0<=RULE_ID)||LA24_0==11||(LA24_0>=13 && LA24_0<=16)||(LA24_0>=18 && LA24_0<=29)||(LA24_0>=31 && LA24_0<=44)||(LA24_0>=46 && LA24_0<=80)||(LA24_0>=82 && LA24_0<=118)) ) {
                alt24=1;
            }
            switch (alt24) {
                case 1 :
                    // InternalRsamlText.g:2099:4: (lv_name_2_0= ruleName )
                    {
                    // InternalRsamlText.g:2099:4: (lv_name_2_0= ruleName )
                    // InternalRsamlText.g:2100:5: lv_name_2_0= ruleName
                    {

                    					newCompositeNode(grammarAccess.getSensorAccess().getNameNameParserRuleCall_2_0());
                    				
                    pushFollow(FOLLOW_4);
                    lv_name_2_0=ruleName();

                    state._fsp--;


                    					if (current==null) {
                    						current = createModelElementForParent(grammarAccess.getSensorRule());
                    					}
                    					set(
                    						current,
                    						"name",
                    						lv_name_2_0,
                    						"org.rsaml.text.RsamlText.Name");
                    					afterParserOrEnumRuleCall();
                    				

                    }


                    }
                    break;

            }

            otherlv_3=(Token)match(input,12,FOLLOW_29); 

            			newLeafNode(otherlv_3, grammarAccess.getSensorAccess().getLeftCurlyBracketKeyword_3());
            		
            // InternalRsamlText.g:2121:3: (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'kind' ( (lv_kind_6_0= RULE_STRING ) ) ) | (otherlv_7= 'dataType' ( (lv_dataType_8_0= ruleDataType ) ) ) | (otherlv_9= 'period' ( (lv_period_10_0= ruleReal ) ) ( (lv_timeUnit_11_0= ruleTimeUnit ) ) ) | this_Unit_12= ruleUnit[$current] )*
            loop25:
            do {
                int alt25=6;
                switch ( input.LA(1) ) {
                case 18:
                    {
                    alt25=1;
                    }
                    break;
                case 52:
                    {
                    alt25=2;
                    }
                    break;
                case 41:
                    {
                    alt25=3;
                    }
                    break;
                case 22:
                    {
                    alt25=4;
                    }
                    break;
                case 19:
                    {
                    alt25=5;
                    }
                    break;

                }

                switch (alt25) {
            	case 1 :
            	    // InternalRsamlText.g:2122:4: this_Described_4= ruleDescribed[$current]
            	    {

            	    				if (current==null) {
            	    					current = createModelElement(grammarAccess.getSensorRule());
            	    				}
            	    				newCompositeNode(grammarAccess.getSensorAccess().getDescribedParserRuleCall_4_0());
            	    			
            	    pushFollow(FOLLOW_29);
            	    this_Described_4=ruleDescribed(current);

            	    state._fsp--;


            	    				current = this_Described_4;
            	    				afterParserOrEnumRuleCall();
            	    			

            	    }
            	    break;
            	case 2 :
            	    // InternalRsamlText.g:2134:4: (otherlv_5= 'kind' ( (lv_kind_6_0= RULE_STRING ) ) )
            	    {
            	    // InternalRsamlText.g:2134:4: (otherlv_5= 'kind' ( (lv_kind_6_0= RULE_STRING ) ) )
            	    // InternalRsamlText.g:2135:5: otherlv_5= 'kind' ( (lv_kind_6_0= RULE_STRING ) )
            	    {
            	    otherlv_5=(Token)match(input,52,FOLLOW_10); 

            	    					newLeafNode(otherlv_5, grammarAccess.getSensorAccess().getKindKeyword_4_1_0());
            	    				
            	    // InternalRsamlText.g:2139:5: ( (lv_kind_6_0= RULE_STRING ) )
            	    // InternalRsamlText.g:2140:6: (lv_kind_6_0= RULE_STRING )
            	    {
            	    // InternalRsamlText.g:2140:6: (lv_kind_6_0= RULE_STRING )
            	    // InternalRsamlText.g:2141:7: lv_kind_6_0= RULE_STRING
            	    {
            	    lv_kind_6_0=(Token)match(input,RULE_STRING,FOLLOW_29); 

            	    							newLeafNode(lv_kind_6_0, grammarAccess.getSensorAccess().getKindSTRINGTerminalRuleCall_4_1_1_0());
            	    						

            	    							if (current==null) {
            	    								current = createModelElement(grammarAccess.getSensorRule());
            	    							}
            	    							setWithLastConsumed(
            	    								current,
            	    								"kind",
            	    								lv_kind_6_0,
            	    								"org.rsaml.text.RsamlText.STRING");
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;
            	case 3 :
            	    // InternalRsamlText.g:2159:4: (otherlv_7= 'dataType' ( (lv_dataType_8_0= ruleDataType ) ) )
            	    {
            	    // InternalRsamlText.g:2159:4: (otherlv_7= 'dataType' ( (lv_dataType_8_0= ruleDataType ) ) )
            	    // InternalRsamlText.g:2160:5: otherlv_7= 'dataType' ( (lv_dataType_8_0= ruleDataType ) )
            	    {
            	    otherlv_7=(Token)match(input,41,FOLLOW_24); 

            	    					newLeafNode(otherlv_7, grammarAccess.getSensorAccess().getDataTypeKeyword_4_2_0());
            	    				
            	    // InternalRsamlText.g:2164:5: ( (lv_dataType_8_0= ruleDataType ) )
            	    // InternalRsamlText.g:2165:6: (lv_dataType_8_0= ruleDataType )
            	    {
            	    // InternalRsamlText.g:2165:6: (lv_dataType_8_0= ruleDataType )
            	    // InternalRsamlText.g:2166:7: lv_dataType_8_0= ruleDataType
            	    {

            	    							newCompositeNode(grammarAccess.getSensorAccess().getDataTypeDataTypeEnumRuleCall_4_2_1_0());
            	    						
            	    pushFollow(FOLLOW_29);
            	    lv_dataType_8_0=ruleDataType();

            	    state._fsp--;


            	    							if (current==null) {
            	    								current = createModelElementForParent(grammarAccess.getSensorRule());
            	    							}
            	    							set(
            	    								current,
            	    								"dataType",
            	    								lv_dataType_8_0,
            	    								"org.rsaml.text.RsamlText.DataType");
            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;
            	case 4 :
            	    // InternalRsamlText.g:2185:4: (otherlv_9= 'period' ( (lv_period_10_0= ruleReal ) ) ( (lv_timeUnit_11_0= ruleTimeUnit ) ) )
            	    {
            	    // InternalRsamlText.g:2185:4: (otherlv_9= 'period' ( (lv_period_10_0= ruleReal ) ) ( (lv_timeUnit_11_0= ruleTimeUnit ) ) )
            	    // InternalRsamlText.g:2186:5: otherlv_9= 'period' ( (lv_period_10_0= ruleReal ) ) ( (lv_timeUnit_11_0= ruleTimeUnit ) )
            	    {
            	    otherlv_9=(Token)match(input,22,FOLLOW_14); 

            	    					newLeafNode(otherlv_9, grammarAccess.getSensorAccess().getPeriodKeyword_4_3_0());
            	    				
            	    // InternalRsamlText.g:2190:5: ( (lv_period_10_0= ruleReal ) )
            	    // InternalRsamlText.g:2191:6: (lv_period_10_0= ruleReal )
            	    {
            	    // InternalRsamlText.g:2191:6: (lv_period_10_0= ruleReal )
            	    // InternalRsamlText.g:2192:7: lv_period_10_0= ruleReal
            	    {

            	    							newCompositeNode(grammarAccess.getSensorAccess().getPeriodRealParserRuleCall_4_3_1_0());
            	    						
            	    pushFollow(FOLLOW_11);
            	    lv_period_10_0=ruleReal();

            	    state._fsp--;


            	    							if (current==null) {
            	    								current = createModelElementForParent(grammarAccess.getSensorRule());
            	    							}
            	    							set(
            	    								current,
            	    								"period",
            	    								lv_period_10_0,
            	    								"org.rsaml.text.RsamlText.Real");
            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }

            	    // InternalRsamlText.g:2209:5: ( (lv_timeUnit_11_0= ruleTimeUnit ) )
            	    // InternalRsamlText.g:2210:6: (lv_timeUnit_11_0= ruleTimeUnit )
            	    {
            	    // InternalRsamlText.g:2210:6: (lv_timeUnit_11_0= ruleTimeUnit )
            	    // InternalRsamlText.g:2211:7: lv_timeUnit_11_0= ruleTimeUnit
            	    {

            	    							newCompositeNode(grammarAccess.getSensorAccess().getTimeUnitTimeUnitEnumRuleCall_4_3_2_0());
            	    						
            	    pushFollow(FOLLOW_29);
            	    lv_timeUnit_11_0=ruleTimeUnit();

            	    state._fsp--;


            	    							if (current==null) {
            	    								current = createModelElementForParent(grammarAccess.getSensorRule());
            	    							}
            	    							set(
            	    								current,
            	    								"timeUnit",
            	    								lv_timeUnit_11_0,
            	    								"org.rsaml.text.RsamlText.TimeUnit");
            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;
            	case 5 :
            	    // InternalRsamlText.g:2230:4: this_Unit_12= ruleUnit[$current]
            	    {

            	    				if (current==null) {
            	    					current = createModelElement(grammarAccess.getSensorRule());
            	    				}
            	    				newCompositeNode(grammarAccess.getSensorAccess().getUnitParserRuleCall_4_4());
            	    			
            	    pushFollow(FOLLOW_29);
            	    this_Unit_12=ruleUnit(current);

            	    state._fsp--;


            	    				current = this_Unit_12;
            	    				afterParserOrEnumRuleCall();
            	    			

            	    }
            	    break;

            	default :
            	    break loop25;
                }
            } while (true);

            otherlv_13=(Token)match(input,17,FOLLOW_2); 

            			newLeafNode(otherlv_13, grammarAccess.getSensorAccess().getRightCurlyBracketKeyword_5());
            		

            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "ruleSensor"


    // $ANTLR start "entryRuleActuator"
    // InternalRsamlText.g:2250:1: entryRuleActuator returns [EObject current=null] : iv_ruleActuator= ruleActuator EOF ;
    public final EObject entryRuleActuator() throws RecognitionException {
        EObject current = null;

        EObject iv_ruleActuator = null;


        try {
            // InternalRsamlText.g:2250:49: (iv_ruleActuator= ruleActuator EOF )
            // InternalRsamlText.g:2251:2: iv_ruleActuator= ruleActuator EOF
            {
             newCompositeNode(grammarAccess.getActuatorRule()); 
            pushFollow(FOLLOW_1);
            iv_ruleActuator=ruleActuator();

            state._fsp--;

             current =iv_ruleActuator; 
            match(input,EOF,FOLLOW_2); 

            }

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "entryRuleActuator"


    // $ANTLR start "ruleActuator"
    // InternalRsamlText.g:2257:1: ruleActuator returns [EObject current=null] : ( () otherlv_1= 'actuator' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'kind' ( (lv_kind_6_0= RULE_STRING ) ) ) | (otherlv_7= 'dataType' ( (lv_dataType_8_0= ruleDataType ) ) ) | (otherlv_9= 'period' ( (lv_period_10_0= ruleReal ) ) ( (lv_timeUnit_11_0= ruleTimeUnit ) ) ) | this_Unit_12= ruleUnit[$current] )* otherlv_13= '}' ) ;
    public final EObject ruleActuator() throws RecognitionException {
        EObject current = null;

        Token otherlv_1=null;
        Token otherlv_3=null;
        Token otherlv_5=null;
        Token lv_kind_6_0=null;
        Token otherlv_7=null;
        Token otherlv_9=null;
        Token otherlv_13=null;
        AntlrDatatypeRuleToken lv_name_2_0 = null;

        EObject this_Described_4 = null;

        Enumerator lv_dataType_8_0 = null;

        AntlrDatatypeRuleToken lv_period_10_0 = null;

        Enumerator lv_timeUnit_11_0 = null;

        EObject this_Unit_12 = null;



        	enterRule();

        try {
            // InternalRsamlText.g:2263:2: ( ( () otherlv_1= 'actuator' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'kind' ( (lv_kind_6_0= RULE_STRING ) ) ) | (otherlv_7= 'dataType' ( (lv_dataType_8_0= ruleDataType ) ) ) | (otherlv_9= 'period' ( (lv_period_10_0= ruleReal ) ) ( (lv_timeUnit_11_0= ruleTimeUnit ) ) ) | this_Unit_12= ruleUnit[$current] )* otherlv_13= '}' ) )
            // InternalRsamlText.g:2264:2: ( () otherlv_1= 'actuator' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'kind' ( (lv_kind_6_0= RULE_STRING ) ) ) | (otherlv_7= 'dataType' ( (lv_dataType_8_0= ruleDataType ) ) ) | (otherlv_9= 'period' ( (lv_period_10_0= ruleReal ) ) ( (lv_timeUnit_11_0= ruleTimeUnit ) ) ) | this_Unit_12= ruleUnit[$current] )* otherlv_13= '}' )
            {
            // InternalRsamlText.g:2264:2: ( () otherlv_1= 'actuator' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'kind' ( (lv_kind_6_0= RULE_STRING ) ) ) | (otherlv_7= 'dataType' ( (lv_dataType_8_0= ruleDataType ) ) ) | (otherlv_9= 'period' ( (lv_period_10_0= ruleReal ) ) ( (lv_timeUnit_11_0= ruleTimeUnit ) ) ) | this_Unit_12= ruleUnit[$current] )* otherlv_13= '}' )
            // InternalRsamlText.g:2265:3: () otherlv_1= 'actuator' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'kind' ( (lv_kind_6_0= RULE_STRING ) ) ) | (otherlv_7= 'dataType' ( (lv_dataType_8_0= ruleDataType ) ) ) | (otherlv_9= 'period' ( (lv_period_10_0= ruleReal ) ) ( (lv_timeUnit_11_0= ruleTimeUnit ) ) ) | this_Unit_12= ruleUnit[$current] )* otherlv_13= '}'
            {
            // InternalRsamlText.g:2265:3: ()
            // InternalRsamlText.g:2266:4: 
            {

            				current = forceCreateModelElement(
            					grammarAccess.getActuatorAccess().getActuatorAction_0(),
            					current);
            			

            }

            otherlv_1=(Token)match(input,53,FOLLOW_3); 

            			newLeafNode(otherlv_1, grammarAccess.getActuatorAccess().getActuatorKeyword_1());
            		
            // InternalRsamlText.g:2276:3: ( (lv_name_2_0= ruleName ) )?
            int alt26=2;
            int LA26_0 = input.LA(1);

            if ( ((LA26_0>=RULE_STRING && LA26_0<=RULE_ID)||LA26_0==11||(LA26_0>=13 && LA26_0<=16)||(LA26_0>=18 && LA26_0<=29)||(LA26_0>=31 && LA26_0<=44)||(LA26_0>=46 && LA26_0<=80)||(LA26_0>=82 && LA26_0<=118)) ) {
                alt26=1;
            }
            switch (alt26) {
                case 1 :
                    // InternalRsamlText.g:2277:4: (lv_name_2_0= ruleName )
                    {
                    // InternalRsamlText.g:2277:4: (lv_name_2_0= ruleName )
                    // InternalRsamlText.g:2278:5: lv_name_2_0= ruleName
                    {

                    					newCompositeNode(grammarAccess.getActuatorAccess().getNameNameParserRuleCall_2_0());
                    				
                    pushFollow(FOLLOW_4);
                    lv_name_2_0=ruleName();

                    state._fsp--;


                    					if (current==null) {
                    						current = createModelElementForParent(grammarAccess.getActuatorRule());
                    					}
                    					set(
                    						current,
                    						"name",
                    						lv_name_2_0,
                    						"org.rsaml.text.RsamlText.Name");
                    					afterParserOrEnumRuleCall();
                    				

                    }


                    }
                    break;

            }

            otherlv_3=(Token)match(input,12,FOLLOW_29); 

            			newLeafNode(otherlv_3, grammarAccess.getActuatorAccess().getLeftCurlyBracketKeyword_3());
            		
            // InternalRsamlText.g:2299:3: (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'kind' ( (lv_kind_6_0= RULE_STRING ) ) ) | (otherlv_7= 'dataType' ( (lv_dataType_8_0= ruleDataType ) ) ) | (otherlv_9= 'period' ( (lv_period_10_0= ruleReal ) ) ( (lv_timeUnit_11_0= ruleTimeUnit ) ) ) | this_Unit_12= ruleUnit[$current] )*
            loop27:
            do {
                int alt27=6;
                switch ( input.LA(1) ) {
                case 18:
                    {
                    alt27=1;
                    }
                    break;
                case 52:
                    {
                    alt27=2;
                    }
                    break;
                case 41:
                    {
                    alt27=3;
                    }
                    break;
                case 22:
                    {
                    alt27=4;
                    }
                    break;
                case 19:
                    {
                    alt27=5;
                    }
                    break;

                }

                switch (alt27) {
            	case 1 :
            	    // InternalRsamlText.g:2300:4: this_Described_4= ruleDescribed[$current]
            	    {

            	    				if (current==null) {
            	    					current = createModelElement(grammarAccess.getActuatorRule());
            	    				}
            	    				newCompositeNode(grammarAccess.getActuatorAccess().getDescribedParserRuleCall_4_0());
            	    			
            	    pushFollow(FOLLOW_29);
            	    this_Described_4=ruleDescribed(current);

            	    state._fsp--;


            	    				current = this_Described_4;
            	    				afterParserOrEnumRuleCall();
            	    			

            	    }
            	    break;
            	case 2 :
            	    // InternalRsamlText.g:2312:4: (otherlv_5= 'kind' ( (lv_kind_6_0= RULE_STRING ) ) )
            	    {
            	    // InternalRsamlText.g:2312:4: (otherlv_5= 'kind' ( (lv_kind_6_0= RULE_STRING ) ) )
            	    // InternalRsamlText.g:2313:5: otherlv_5= 'kind' ( (lv_kind_6_0= RULE_STRING ) )
            	    {
            	    otherlv_5=(Token)match(input,52,FOLLOW_10); 

            	    					newLeafNode(otherlv_5, grammarAccess.getActuatorAccess().getKindKeyword_4_1_0());
            	    				
            	    // InternalRsamlText.g:2317:5: ( (lv_kind_6_0= RULE_STRING ) )
            	    // InternalRsamlText.g:2318:6: (lv_kind_6_0= RULE_STRING )
            	    {
            	    // InternalRsamlText.g:2318:6: (lv_kind_6_0= RULE_STRING )
            	    // InternalRsamlText.g:2319:7: lv_kind_6_0= RULE_STRING
            	    {
            	    lv_kind_6_0=(Token)match(input,RULE_STRING,FOLLOW_29); 

            	    							newLeafNode(lv_kind_6_0, grammarAccess.getActuatorAccess().getKindSTRINGTerminalRuleCall_4_1_1_0());
            	    						

            	    							if (current==null) {
            	    								current = createModelElement(grammarAccess.getActuatorRule());
            	    							}
            	    							setWithLastConsumed(
            	    								current,
            	    								"kind",
            	    								lv_kind_6_0,
            	    								"org.rsaml.text.RsamlText.STRING");
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;
            	case 3 :
            	    // InternalRsamlText.g:2337:4: (otherlv_7= 'dataType' ( (lv_dataType_8_0= ruleDataType ) ) )
            	    {
            	    // InternalRsamlText.g:2337:4: (otherlv_7= 'dataType' ( (lv_dataType_8_0= ruleDataType ) ) )
            	    // InternalRsamlText.g:2338:5: otherlv_7= 'dataType' ( (lv_dataType_8_0= ruleDataType ) )
            	    {
            	    otherlv_7=(Token)match(input,41,FOLLOW_24); 

            	    					newLeafNode(otherlv_7, grammarAccess.getActuatorAccess().getDataTypeKeyword_4_2_0());
            	    				
            	    // InternalRsamlText.g:2342:5: ( (lv_dataType_8_0= ruleDataType ) )
            	    // InternalRsamlText.g:2343:6: (lv_dataType_8_0= ruleDataType )
            	    {
            	    // InternalRsamlText.g:2343:6: (lv_dataType_8_0= ruleDataType )
            	    // InternalRsamlText.g:2344:7: lv_dataType_8_0= ruleDataType
            	    {

            	    							newCompositeNode(grammarAccess.getActuatorAccess().getDataTypeDataTypeEnumRuleCall_4_2_1_0());
            	    						
            	    pushFollow(FOLLOW_29);
            	    lv_dataType_8_0=ruleDataType();

            	    state._fsp--;


            	    							if (current==null) {
            	    								current = createModelElementForParent(grammarAccess.getActuatorRule());
            	    							}
            	    							set(
            	    								current,
            	    								"dataType",
            	    								lv_dataType_8_0,
            	    								"org.rsaml.text.RsamlText.DataType");
            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;
            	case 4 :
            	    // InternalRsamlText.g:2363:4: (otherlv_9= 'period' ( (lv_period_10_0= ruleReal ) ) ( (lv_timeUnit_11_0= ruleTimeUnit ) ) )
            	    {
            	    // InternalRsamlText.g:2363:4: (otherlv_9= 'period' ( (lv_period_10_0= ruleReal ) ) ( (lv_timeUnit_11_0= ruleTimeUnit ) ) )
            	    // InternalRsamlText.g:2364:5: otherlv_9= 'period' ( (lv_period_10_0= ruleReal ) ) ( (lv_timeUnit_11_0= ruleTimeUnit ) )
            	    {
            	    otherlv_9=(Token)match(input,22,FOLLOW_14); 

            	    					newLeafNode(otherlv_9, grammarAccess.getActuatorAccess().getPeriodKeyword_4_3_0());
            	    				
            	    // InternalRsamlText.g:2368:5: ( (lv_period_10_0= ruleReal ) )
            	    // InternalRsamlText.g:2369:6: (lv_period_10_0= ruleReal )
            	    {
            	    // InternalRsamlText.g:2369:6: (lv_period_10_0= ruleReal )
            	    // InternalRsamlText.g:2370:7: lv_period_10_0= ruleReal
            	    {

            	    							newCompositeNode(grammarAccess.getActuatorAccess().getPeriodRealParserRuleCall_4_3_1_0());
            	    						
            	    pushFollow(FOLLOW_11);
            	    lv_period_10_0=ruleReal();

            	    state._fsp--;


            	    							if (current==null) {
            	    								current = createModelElementForParent(grammarAccess.getActuatorRule());
            	    							}
            	    							set(
            	    								current,
            	    								"period",
            	    								lv_period_10_0,
            	    								"org.rsaml.text.RsamlText.Real");
            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }

            	    // InternalRsamlText.g:2387:5: ( (lv_timeUnit_11_0= ruleTimeUnit ) )
            	    // InternalRsamlText.g:2388:6: (lv_timeUnit_11_0= ruleTimeUnit )
            	    {
            	    // InternalRsamlText.g:2388:6: (lv_timeUnit_11_0= ruleTimeUnit )
            	    // InternalRsamlText.g:2389:7: lv_timeUnit_11_0= ruleTimeUnit
            	    {

            	    							newCompositeNode(grammarAccess.getActuatorAccess().getTimeUnitTimeUnitEnumRuleCall_4_3_2_0());
            	    						
            	    pushFollow(FOLLOW_29);
            	    lv_timeUnit_11_0=ruleTimeUnit();

            	    state._fsp--;


            	    							if (current==null) {
            	    								current = createModelElementForParent(grammarAccess.getActuatorRule());
            	    							}
            	    							set(
            	    								current,
            	    								"timeUnit",
            	    								lv_timeUnit_11_0,
            	    								"org.rsaml.text.RsamlText.TimeUnit");
            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;
            	case 5 :
            	    // InternalRsamlText.g:2408:4: this_Unit_12= ruleUnit[$current]
            	    {

            	    				if (current==null) {
            	    					current = createModelElement(grammarAccess.getActuatorRule());
            	    				}
            	    				newCompositeNode(grammarAccess.getActuatorAccess().getUnitParserRuleCall_4_4());
            	    			
            	    pushFollow(FOLLOW_29);
            	    this_Unit_12=ruleUnit(current);

            	    state._fsp--;


            	    				current = this_Unit_12;
            	    				afterParserOrEnumRuleCall();
            	    			

            	    }
            	    break;

            	default :
            	    break loop27;
                }
            } while (true);

            otherlv_13=(Token)match(input,17,FOLLOW_2); 

            			newLeafNode(otherlv_13, grammarAccess.getActuatorAccess().getRightCurlyBracketKeyword_5());
            		

            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "ruleActuator"


    // $ANTLR start "entryRuleMission"
    // InternalRsamlText.g:2428:1: entryRuleMission returns [EObject current=null] : iv_ruleMission= ruleMission EOF ;
    public final EObject entryRuleMission() throws RecognitionException {
        EObject current = null;

        EObject iv_ruleMission = null;


        try {
            // InternalRsamlText.g:2428:48: (iv_ruleMission= ruleMission EOF )
            // InternalRsamlText.g:2429:2: iv_ruleMission= ruleMission EOF
            {
             newCompositeNode(grammarAccess.getMissionRule()); 
            pushFollow(FOLLOW_1);
            iv_ruleMission=ruleMission();

            state._fsp--;

             current =iv_ruleMission; 
            match(input,EOF,FOLLOW_2); 

            }

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "entryRuleMission"


    // $ANTLR start "ruleMission"
    // InternalRsamlText.g:2435:1: ruleMission returns [EObject current=null] : ( () otherlv_1= 'mission' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | ( (lv_goals_5_0= ruleGoal ) ) | ( (lv_plans_6_0= rulePlan ) ) )* otherlv_7= '}' ) ;
    public final EObject ruleMission() throws RecognitionException {
        EObject current = null;

        Token otherlv_1=null;
        Token otherlv_3=null;
        Token otherlv_7=null;
        AntlrDatatypeRuleToken lv_name_2_0 = null;

        EObject this_Described_4 = null;

        EObject lv_goals_5_0 = null;

        EObject lv_plans_6_0 = null;



        	enterRule();

        try {
            // InternalRsamlText.g:2441:2: ( ( () otherlv_1= 'mission' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | ( (lv_goals_5_0= ruleGoal ) ) | ( (lv_plans_6_0= rulePlan ) ) )* otherlv_7= '}' ) )
            // InternalRsamlText.g:2442:2: ( () otherlv_1= 'mission' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | ( (lv_goals_5_0= ruleGoal ) ) | ( (lv_plans_6_0= rulePlan ) ) )* otherlv_7= '}' )
            {
            // InternalRsamlText.g:2442:2: ( () otherlv_1= 'mission' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | ( (lv_goals_5_0= ruleGoal ) ) | ( (lv_plans_6_0= rulePlan ) ) )* otherlv_7= '}' )
            // InternalRsamlText.g:2443:3: () otherlv_1= 'mission' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | ( (lv_goals_5_0= ruleGoal ) ) | ( (lv_plans_6_0= rulePlan ) ) )* otherlv_7= '}'
            {
            // InternalRsamlText.g:2443:3: ()
            // InternalRsamlText.g:2444:4: 
            {

            				current = forceCreateModelElement(
            					grammarAccess.getMissionAccess().getMissionAction_0(),
            					current);
            			

            }

            otherlv_1=(Token)match(input,54,FOLLOW_3); 

            			newLeafNode(otherlv_1, grammarAccess.getMissionAccess().getMissionKeyword_1());
            		
            // InternalRsamlText.g:2454:3: ( (lv_name_2_0= ruleName ) )?
            int alt28=2;
            int LA28_0 = input.LA(1);

            if ( ((LA28_0>=RULE_STRING && LA28_0<=RULE_ID)||LA28_0==11||(LA28_0>=13 && LA28_0<=16)||(LA28_0>=18 && LA28_0<=29)||(LA28_0>=31 && LA28_0<=44)||(LA28_0>=46 && LA28_0<=80)||(LA28_0>=82 && LA28_0<=118)) ) {
                alt28=1;
            }
            switch (alt28) {
                case 1 :
                    // InternalRsamlText.g:2455:4: (lv_name_2_0= ruleName )
                    {
                    // InternalRsamlText.g:2455:4: (lv_name_2_0= ruleName )
                    // InternalRsamlText.g:2456:5: lv_name_2_0= ruleName
                    {

                    					newCompositeNode(grammarAccess.getMissionAccess().getNameNameParserRuleCall_2_0());
                    				
                    pushFollow(FOLLOW_4);
                    lv_name_2_0=ruleName();

                    state._fsp--;


                    					if (current==null) {
                    						current = createModelElementForParent(grammarAccess.getMissionRule());
                    					}
                    					set(
                    						current,
                    						"name",
                    						lv_name_2_0,
                    						"org.rsaml.text.RsamlText.Name");
                    					afterParserOrEnumRuleCall();
                    				

                    }


                    }
                    break;

            }

            otherlv_3=(Token)match(input,12,FOLLOW_30); 

            			newLeafNode(otherlv_3, grammarAccess.getMissionAccess().getLeftCurlyBracketKeyword_3());
            		
            // InternalRsamlText.g:2477:3: (this_Described_4= ruleDescribed[$current] | ( (lv_goals_5_0= ruleGoal ) ) | ( (lv_plans_6_0= rulePlan ) ) )*
            loop29:
            do {
                int alt29=4;
                switch ( input.LA(1) ) {
                case 18:
                    {
                    alt29=1;
                    }
                    break;
                case 55:
                    {
                    alt29=2;
                    }
                    break;
                case 57:
                    {
                    alt29=3;
                    }
                    break;

                }

                switch (alt29) {
            	case 1 :
            	    // InternalRsamlText.g:2478:4: this_Described_4= ruleDescribed[$current]
            	    {

            	    				if (current==null) {
            	    					current = createModelElement(grammarAccess.getMissionRule());
            	    				}
            	    				newCompositeNode(grammarAccess.getMissionAccess().getDescribedParserRuleCall_4_0());
            	    			
            	    pushFollow(FOLLOW_30);
            	    this_Described_4=ruleDescribed(current);

            	    state._fsp--;


            	    				current = this_Described_4;
            	    				afterParserOrEnumRuleCall();
            	    			

            	    }
            	    break;
            	case 2 :
            	    // InternalRsamlText.g:2490:4: ( (lv_goals_5_0= ruleGoal ) )
            	    {
            	    // InternalRsamlText.g:2490:4: ( (lv_goals_5_0= ruleGoal ) )
            	    // InternalRsamlText.g:2491:5: (lv_goals_5_0= ruleGoal )
            	    {
            	    // InternalRsamlText.g:2491:5: (lv_goals_5_0= ruleGoal )
            	    // InternalRsamlText.g:2492:6: lv_goals_5_0= ruleGoal
            	    {

            	    						newCompositeNode(grammarAccess.getMissionAccess().getGoalsGoalParserRuleCall_4_1_0());
            	    					
            	    pushFollow(FOLLOW_30);
            	    lv_goals_5_0=ruleGoal();

            	    state._fsp--;


            	    						if (current==null) {
            	    							current = createModelElementForParent(grammarAccess.getMissionRule());
            	    						}
            	    						add(
            	    							current,
            	    							"goals",
            	    							lv_goals_5_0,
            	    							"org.rsaml.text.RsamlText.Goal");
            	    						afterParserOrEnumRuleCall();
            	    					

            	    }


            	    }


            	    }
            	    break;
            	case 3 :
            	    // InternalRsamlText.g:2510:4: ( (lv_plans_6_0= rulePlan ) )
            	    {
            	    // InternalRsamlText.g:2510:4: ( (lv_plans_6_0= rulePlan ) )
            	    // InternalRsamlText.g:2511:5: (lv_plans_6_0= rulePlan )
            	    {
            	    // InternalRsamlText.g:2511:5: (lv_plans_6_0= rulePlan )
            	    // InternalRsamlText.g:2512:6: lv_plans_6_0= rulePlan
            	    {

            	    						newCompositeNode(grammarAccess.getMissionAccess().getPlansPlanParserRuleCall_4_2_0());
            	    					
            	    pushFollow(FOLLOW_30);
            	    lv_plans_6_0=rulePlan();

            	    state._fsp--;


            	    						if (current==null) {
            	    							current = createModelElementForParent(grammarAccess.getMissionRule());
            	    						}
            	    						add(
            	    							current,
            	    							"plans",
            	    							lv_plans_6_0,
            	    							"org.rsaml.text.RsamlText.Plan");
            	    						afterParserOrEnumRuleCall();
            	    					

            	    }


            	    }


            	    }
            	    break;

            	default :
            	    break loop29;
                }
            } while (true);

            otherlv_7=(Token)match(input,17,FOLLOW_2); 

            			newLeafNode(otherlv_7, grammarAccess.getMissionAccess().getRightCurlyBracketKeyword_5());
            		

            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "ruleMission"


    // $ANTLR start "entryRuleGoal"
    // InternalRsamlText.g:2538:1: entryRuleGoal returns [EObject current=null] : iv_ruleGoal= ruleGoal EOF ;
    public final EObject entryRuleGoal() throws RecognitionException {
        EObject current = null;

        EObject iv_ruleGoal = null;


        try {
            // InternalRsamlText.g:2538:45: (iv_ruleGoal= ruleGoal EOF )
            // InternalRsamlText.g:2539:2: iv_ruleGoal= ruleGoal EOF
            {
             newCompositeNode(grammarAccess.getGoalRule()); 
            pushFollow(FOLLOW_1);
            iv_ruleGoal=ruleGoal();

            state._fsp--;

             current =iv_ruleGoal; 
            match(input,EOF,FOLLOW_2); 

            }

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "entryRuleGoal"


    // $ANTLR start "ruleGoal"
    // InternalRsamlText.g:2545:1: ruleGoal returns [EObject current=null] : ( () otherlv_1= 'goal' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'priority' ( (lv_priority_6_0= ruleInteger ) ) ) | ( (lv_subGoals_7_0= ruleGoal ) ) )* otherlv_8= '}' ) ;
    public final EObject ruleGoal() throws RecognitionException {
        EObject current = null;

        Token otherlv_1=null;
        Token otherlv_3=null;
        Token otherlv_5=null;
        Token otherlv_8=null;
        AntlrDatatypeRuleToken lv_name_2_0 = null;

        EObject this_Described_4 = null;

        AntlrDatatypeRuleToken lv_priority_6_0 = null;

        EObject lv_subGoals_7_0 = null;



        	enterRule();

        try {
            // InternalRsamlText.g:2551:2: ( ( () otherlv_1= 'goal' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'priority' ( (lv_priority_6_0= ruleInteger ) ) ) | ( (lv_subGoals_7_0= ruleGoal ) ) )* otherlv_8= '}' ) )
            // InternalRsamlText.g:2552:2: ( () otherlv_1= 'goal' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'priority' ( (lv_priority_6_0= ruleInteger ) ) ) | ( (lv_subGoals_7_0= ruleGoal ) ) )* otherlv_8= '}' )
            {
            // InternalRsamlText.g:2552:2: ( () otherlv_1= 'goal' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'priority' ( (lv_priority_6_0= ruleInteger ) ) ) | ( (lv_subGoals_7_0= ruleGoal ) ) )* otherlv_8= '}' )
            // InternalRsamlText.g:2553:3: () otherlv_1= 'goal' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'priority' ( (lv_priority_6_0= ruleInteger ) ) ) | ( (lv_subGoals_7_0= ruleGoal ) ) )* otherlv_8= '}'
            {
            // InternalRsamlText.g:2553:3: ()
            // InternalRsamlText.g:2554:4: 
            {

            				current = forceCreateModelElement(
            					grammarAccess.getGoalAccess().getGoalAction_0(),
            					current);
            			

            }

            otherlv_1=(Token)match(input,55,FOLLOW_3); 

            			newLeafNode(otherlv_1, grammarAccess.getGoalAccess().getGoalKeyword_1());
            		
            // InternalRsamlText.g:2564:3: ( (lv_name_2_0= ruleName ) )?
            int alt30=2;
            int LA30_0 = input.LA(1);

            if ( ((LA30_0>=RULE_STRING && LA30_0<=RULE_ID)||LA30_0==11||(LA30_0>=13 && LA30_0<=16)||(LA30_0>=18 && LA30_0<=29)||(LA30_0>=31 && LA30_0<=44)||(LA30_0>=46 && LA30_0<=80)||(LA30_0>=82 && LA30_0<=118)) ) {
                alt30=1;
            }
            switch (alt30) {
                case 1 :
                    // InternalRsamlText.g:2565:4: (lv_name_2_0= ruleName )
                    {
                    // InternalRsamlText.g:2565:4: (lv_name_2_0= ruleName )
                    // InternalRsamlText.g:2566:5: lv_name_2_0= ruleName
                    {

                    					newCompositeNode(grammarAccess.getGoalAccess().getNameNameParserRuleCall_2_0());
                    				
                    pushFollow(FOLLOW_4);
                    lv_name_2_0=ruleName();

                    state._fsp--;


                    					if (current==null) {
                    						current = createModelElementForParent(grammarAccess.getGoalRule());
                    					}
                    					set(
                    						current,
                    						"name",
                    						lv_name_2_0,
                    						"org.rsaml.text.RsamlText.Name");
                    					afterParserOrEnumRuleCall();
                    				

                    }


                    }
                    break;

            }

            otherlv_3=(Token)match(input,12,FOLLOW_31); 

            			newLeafNode(otherlv_3, grammarAccess.getGoalAccess().getLeftCurlyBracketKeyword_3());
            		
            // InternalRsamlText.g:2587:3: (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'priority' ( (lv_priority_6_0= ruleInteger ) ) ) | ( (lv_subGoals_7_0= ruleGoal ) ) )*
            loop31:
            do {
                int alt31=4;
                switch ( input.LA(1) ) {
                case 18:
                    {
                    alt31=1;
                    }
                    break;
                case 56:
                    {
                    alt31=2;
                    }
                    break;
                case 55:
                    {
                    alt31=3;
                    }
                    break;

                }

                switch (alt31) {
            	case 1 :
            	    // InternalRsamlText.g:2588:4: this_Described_4= ruleDescribed[$current]
            	    {

            	    				if (current==null) {
            	    					current = createModelElement(grammarAccess.getGoalRule());
            	    				}
            	    				newCompositeNode(grammarAccess.getGoalAccess().getDescribedParserRuleCall_4_0());
            	    			
            	    pushFollow(FOLLOW_31);
            	    this_Described_4=ruleDescribed(current);

            	    state._fsp--;


            	    				current = this_Described_4;
            	    				afterParserOrEnumRuleCall();
            	    			

            	    }
            	    break;
            	case 2 :
            	    // InternalRsamlText.g:2600:4: (otherlv_5= 'priority' ( (lv_priority_6_0= ruleInteger ) ) )
            	    {
            	    // InternalRsamlText.g:2600:4: (otherlv_5= 'priority' ( (lv_priority_6_0= ruleInteger ) ) )
            	    // InternalRsamlText.g:2601:5: otherlv_5= 'priority' ( (lv_priority_6_0= ruleInteger ) )
            	    {
            	    otherlv_5=(Token)match(input,56,FOLLOW_7); 

            	    					newLeafNode(otherlv_5, grammarAccess.getGoalAccess().getPriorityKeyword_4_1_0());
            	    				
            	    // InternalRsamlText.g:2605:5: ( (lv_priority_6_0= ruleInteger ) )
            	    // InternalRsamlText.g:2606:6: (lv_priority_6_0= ruleInteger )
            	    {
            	    // InternalRsamlText.g:2606:6: (lv_priority_6_0= ruleInteger )
            	    // InternalRsamlText.g:2607:7: lv_priority_6_0= ruleInteger
            	    {

            	    							newCompositeNode(grammarAccess.getGoalAccess().getPriorityIntegerParserRuleCall_4_1_1_0());
            	    						
            	    pushFollow(FOLLOW_31);
            	    lv_priority_6_0=ruleInteger();

            	    state._fsp--;


            	    							if (current==null) {
            	    								current = createModelElementForParent(grammarAccess.getGoalRule());
            	    							}
            	    							set(
            	    								current,
            	    								"priority",
            	    								lv_priority_6_0,
            	    								"org.rsaml.text.RsamlText.Integer");
            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;
            	case 3 :
            	    // InternalRsamlText.g:2626:4: ( (lv_subGoals_7_0= ruleGoal ) )
            	    {
            	    // InternalRsamlText.g:2626:4: ( (lv_subGoals_7_0= ruleGoal ) )
            	    // InternalRsamlText.g:2627:5: (lv_subGoals_7_0= ruleGoal )
            	    {
            	    // InternalRsamlText.g:2627:5: (lv_subGoals_7_0= ruleGoal )
            	    // InternalRsamlText.g:2628:6: lv_subGoals_7_0= ruleGoal
            	    {

            	    						newCompositeNode(grammarAccess.getGoalAccess().getSubGoalsGoalParserRuleCall_4_2_0());
            	    					
            	    pushFollow(FOLLOW_31);
            	    lv_subGoals_7_0=ruleGoal();

            	    state._fsp--;


            	    						if (current==null) {
            	    							current = createModelElementForParent(grammarAccess.getGoalRule());
            	    						}
            	    						add(
            	    							current,
            	    							"subGoals",
            	    							lv_subGoals_7_0,
            	    							"org.rsaml.text.RsamlText.Goal");
            	    						afterParserOrEnumRuleCall();
            	    					

            	    }


            	    }


            	    }
            	    break;

            	default :
            	    break loop31;
                }
            } while (true);

            otherlv_8=(Token)match(input,17,FOLLOW_2); 

            			newLeafNode(otherlv_8, grammarAccess.getGoalAccess().getRightCurlyBracketKeyword_5());
            		

            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "ruleGoal"


    // $ANTLR start "entryRulePlan"
    // InternalRsamlText.g:2654:1: entryRulePlan returns [EObject current=null] : iv_rulePlan= rulePlan EOF ;
    public final EObject entryRulePlan() throws RecognitionException {
        EObject current = null;

        EObject iv_rulePlan = null;


        try {
            // InternalRsamlText.g:2654:45: (iv_rulePlan= rulePlan EOF )
            // InternalRsamlText.g:2655:2: iv_rulePlan= rulePlan EOF
            {
             newCompositeNode(grammarAccess.getPlanRule()); 
            pushFollow(FOLLOW_1);
            iv_rulePlan=rulePlan();

            state._fsp--;

             current =iv_rulePlan; 
            match(input,EOF,FOLLOW_2); 

            }

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "entryRulePlan"


    // $ANTLR start "rulePlan"
    // InternalRsamlText.g:2661:1: rulePlan returns [EObject current=null] : ( () otherlv_1= 'plan' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'achieves' ( ( ruleQualifiedName ) ) (otherlv_7= ',' ( ( ruleQualifiedName ) ) )* ) | ( (lv_activities_9_0= ruleActivity ) ) )* otherlv_10= '}' ) ;
    public final EObject rulePlan() throws RecognitionException {
        EObject current = null;

        Token otherlv_1=null;
        Token otherlv_3=null;
        Token otherlv_5=null;
        Token otherlv_7=null;
        Token otherlv_10=null;
        AntlrDatatypeRuleToken lv_name_2_0 = null;

        EObject this_Described_4 = null;

        EObject lv_activities_9_0 = null;



        	enterRule();

        try {
            // InternalRsamlText.g:2667:2: ( ( () otherlv_1= 'plan' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'achieves' ( ( ruleQualifiedName ) ) (otherlv_7= ',' ( ( ruleQualifiedName ) ) )* ) | ( (lv_activities_9_0= ruleActivity ) ) )* otherlv_10= '}' ) )
            // InternalRsamlText.g:2668:2: ( () otherlv_1= 'plan' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'achieves' ( ( ruleQualifiedName ) ) (otherlv_7= ',' ( ( ruleQualifiedName ) ) )* ) | ( (lv_activities_9_0= ruleActivity ) ) )* otherlv_10= '}' )
            {
            // InternalRsamlText.g:2668:2: ( () otherlv_1= 'plan' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'achieves' ( ( ruleQualifiedName ) ) (otherlv_7= ',' ( ( ruleQualifiedName ) ) )* ) | ( (lv_activities_9_0= ruleActivity ) ) )* otherlv_10= '}' )
            // InternalRsamlText.g:2669:3: () otherlv_1= 'plan' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'achieves' ( ( ruleQualifiedName ) ) (otherlv_7= ',' ( ( ruleQualifiedName ) ) )* ) | ( (lv_activities_9_0= ruleActivity ) ) )* otherlv_10= '}'
            {
            // InternalRsamlText.g:2669:3: ()
            // InternalRsamlText.g:2670:4: 
            {

            				current = forceCreateModelElement(
            					grammarAccess.getPlanAccess().getPlanAction_0(),
            					current);
            			

            }

            otherlv_1=(Token)match(input,57,FOLLOW_3); 

            			newLeafNode(otherlv_1, grammarAccess.getPlanAccess().getPlanKeyword_1());
            		
            // InternalRsamlText.g:2680:3: ( (lv_name_2_0= ruleName ) )?
            int alt32=2;
            int LA32_0 = input.LA(1);

            if ( ((LA32_0>=RULE_STRING && LA32_0<=RULE_ID)||LA32_0==11||(LA32_0>=13 && LA32_0<=16)||(LA32_0>=18 && LA32_0<=29)||(LA32_0>=31 && LA32_0<=44)||(LA32_0>=46 && LA32_0<=80)||(LA32_0>=82 && LA32_0<=118)) ) {
                alt32=1;
            }
            switch (alt32) {
                case 1 :
                    // InternalRsamlText.g:2681:4: (lv_name_2_0= ruleName )
                    {
                    // InternalRsamlText.g:2681:4: (lv_name_2_0= ruleName )
                    // InternalRsamlText.g:2682:5: lv_name_2_0= ruleName
                    {

                    					newCompositeNode(grammarAccess.getPlanAccess().getNameNameParserRuleCall_2_0());
                    				
                    pushFollow(FOLLOW_4);
                    lv_name_2_0=ruleName();

                    state._fsp--;


                    					if (current==null) {
                    						current = createModelElementForParent(grammarAccess.getPlanRule());
                    					}
                    					set(
                    						current,
                    						"name",
                    						lv_name_2_0,
                    						"org.rsaml.text.RsamlText.Name");
                    					afterParserOrEnumRuleCall();
                    				

                    }


                    }
                    break;

            }

            otherlv_3=(Token)match(input,12,FOLLOW_32); 

            			newLeafNode(otherlv_3, grammarAccess.getPlanAccess().getLeftCurlyBracketKeyword_3());
            		
            // InternalRsamlText.g:2703:3: (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'achieves' ( ( ruleQualifiedName ) ) (otherlv_7= ',' ( ( ruleQualifiedName ) ) )* ) | ( (lv_activities_9_0= ruleActivity ) ) )*
            loop34:
            do {
                int alt34=4;
                switch ( input.LA(1) ) {
                case 18:
                    {
                    alt34=1;
                    }
                    break;
                case 58:
                    {
                    alt34=2;
                    }
                    break;
                case 59:
                    {
                    alt34=3;
                    }
                    break;

                }

                switch (alt34) {
            	case 1 :
            	    // InternalRsamlText.g:2704:4: this_Described_4= ruleDescribed[$current]
            	    {

            	    				if (current==null) {
            	    					current = createModelElement(grammarAccess.getPlanRule());
            	    				}
            	    				newCompositeNode(grammarAccess.getPlanAccess().getDescribedParserRuleCall_4_0());
            	    			
            	    pushFollow(FOLLOW_32);
            	    this_Described_4=ruleDescribed(current);

            	    state._fsp--;


            	    				current = this_Described_4;
            	    				afterParserOrEnumRuleCall();
            	    			

            	    }
            	    break;
            	case 2 :
            	    // InternalRsamlText.g:2716:4: (otherlv_5= 'achieves' ( ( ruleQualifiedName ) ) (otherlv_7= ',' ( ( ruleQualifiedName ) ) )* )
            	    {
            	    // InternalRsamlText.g:2716:4: (otherlv_5= 'achieves' ( ( ruleQualifiedName ) ) (otherlv_7= ',' ( ( ruleQualifiedName ) ) )* )
            	    // InternalRsamlText.g:2717:5: otherlv_5= 'achieves' ( ( ruleQualifiedName ) ) (otherlv_7= ',' ( ( ruleQualifiedName ) ) )*
            	    {
            	    otherlv_5=(Token)match(input,58,FOLLOW_17); 

            	    					newLeafNode(otherlv_5, grammarAccess.getPlanAccess().getAchievesKeyword_4_1_0());
            	    				
            	    // InternalRsamlText.g:2721:5: ( ( ruleQualifiedName ) )
            	    // InternalRsamlText.g:2722:6: ( ruleQualifiedName )
            	    {
            	    // InternalRsamlText.g:2722:6: ( ruleQualifiedName )
            	    // InternalRsamlText.g:2723:7: ruleQualifiedName
            	    {

            	    							if (current==null) {
            	    								current = createModelElement(grammarAccess.getPlanRule());
            	    							}
            	    						

            	    							newCompositeNode(grammarAccess.getPlanAccess().getAchievesGoalCrossReference_4_1_1_0());
            	    						
            	    pushFollow(FOLLOW_33);
            	    ruleQualifiedName();

            	    state._fsp--;


            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }

            	    // InternalRsamlText.g:2737:5: (otherlv_7= ',' ( ( ruleQualifiedName ) ) )*
            	    loop33:
            	    do {
            	        int alt33=2;
            	        int LA33_0 = input.LA(1);

            	        if ( (LA33_0==30) ) {
            	            alt33=1;
            	        }


            	        switch (alt33) {
            	    	case 1 :
            	    	    // InternalRsamlText.g:2738:6: otherlv_7= ',' ( ( ruleQualifiedName ) )
            	    	    {
            	    	    otherlv_7=(Token)match(input,30,FOLLOW_17); 

            	    	    						newLeafNode(otherlv_7, grammarAccess.getPlanAccess().getCommaKeyword_4_1_2_0());
            	    	    					
            	    	    // InternalRsamlText.g:2742:6: ( ( ruleQualifiedName ) )
            	    	    // InternalRsamlText.g:2743:7: ( ruleQualifiedName )
            	    	    {
            	    	    // InternalRsamlText.g:2743:7: ( ruleQualifiedName )
            	    	    // InternalRsamlText.g:2744:8: ruleQualifiedName
            	    	    {

            	    	    								if (current==null) {
            	    	    									current = createModelElement(grammarAccess.getPlanRule());
            	    	    								}
            	    	    							

            	    	    								newCompositeNode(grammarAccess.getPlanAccess().getAchievesGoalCrossReference_4_1_2_1_0());
            	    	    							
            	    	    pushFollow(FOLLOW_33);
            	    	    ruleQualifiedName();

            	    	    state._fsp--;


            	    	    								afterParserOrEnumRuleCall();
            	    	    							

            	    	    }


            	    	    }


            	    	    }
            	    	    break;

            	    	default :
            	    	    break loop33;
            	        }
            	    } while (true);


            	    }


            	    }
            	    break;
            	case 3 :
            	    // InternalRsamlText.g:2761:4: ( (lv_activities_9_0= ruleActivity ) )
            	    {
            	    // InternalRsamlText.g:2761:4: ( (lv_activities_9_0= ruleActivity ) )
            	    // InternalRsamlText.g:2762:5: (lv_activities_9_0= ruleActivity )
            	    {
            	    // InternalRsamlText.g:2762:5: (lv_activities_9_0= ruleActivity )
            	    // InternalRsamlText.g:2763:6: lv_activities_9_0= ruleActivity
            	    {

            	    						newCompositeNode(grammarAccess.getPlanAccess().getActivitiesActivityParserRuleCall_4_2_0());
            	    					
            	    pushFollow(FOLLOW_32);
            	    lv_activities_9_0=ruleActivity();

            	    state._fsp--;


            	    						if (current==null) {
            	    							current = createModelElementForParent(grammarAccess.getPlanRule());
            	    						}
            	    						add(
            	    							current,
            	    							"activities",
            	    							lv_activities_9_0,
            	    							"org.rsaml.text.RsamlText.Activity");
            	    						afterParserOrEnumRuleCall();
            	    					

            	    }


            	    }


            	    }
            	    break;

            	default :
            	    break loop34;
                }
            } while (true);

            otherlv_10=(Token)match(input,17,FOLLOW_2); 

            			newLeafNode(otherlv_10, grammarAccess.getPlanAccess().getRightCurlyBracketKeyword_5());
            		

            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "rulePlan"


    // $ANTLR start "entryRuleActivity"
    // InternalRsamlText.g:2789:1: entryRuleActivity returns [EObject current=null] : iv_ruleActivity= ruleActivity EOF ;
    public final EObject entryRuleActivity() throws RecognitionException {
        EObject current = null;

        EObject iv_ruleActivity = null;


        try {
            // InternalRsamlText.g:2789:49: (iv_ruleActivity= ruleActivity EOF )
            // InternalRsamlText.g:2790:2: iv_ruleActivity= ruleActivity EOF
            {
             newCompositeNode(grammarAccess.getActivityRule()); 
            pushFollow(FOLLOW_1);
            iv_ruleActivity=ruleActivity();

            state._fsp--;

             current =iv_ruleActivity; 
            match(input,EOF,FOLLOW_2); 

            }

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "entryRuleActivity"


    // $ANTLR start "ruleActivity"
    // InternalRsamlText.g:2796:1: ruleActivity returns [EObject current=null] : ( () otherlv_1= 'activity' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | this_RealTime_5= ruleRealTime[$current] | (otherlv_6= 'actions' ( ( ruleQualifiedName ) ) (otherlv_8= ',' ( ( ruleQualifiedName ) ) )* ) )* otherlv_10= '}' ) ;
    public final EObject ruleActivity() throws RecognitionException {
        EObject current = null;

        Token otherlv_1=null;
        Token otherlv_3=null;
        Token otherlv_6=null;
        Token otherlv_8=null;
        Token otherlv_10=null;
        AntlrDatatypeRuleToken lv_name_2_0 = null;

        EObject this_Described_4 = null;

        EObject this_RealTime_5 = null;



        	enterRule();

        try {
            // InternalRsamlText.g:2802:2: ( ( () otherlv_1= 'activity' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | this_RealTime_5= ruleRealTime[$current] | (otherlv_6= 'actions' ( ( ruleQualifiedName ) ) (otherlv_8= ',' ( ( ruleQualifiedName ) ) )* ) )* otherlv_10= '}' ) )
            // InternalRsamlText.g:2803:2: ( () otherlv_1= 'activity' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | this_RealTime_5= ruleRealTime[$current] | (otherlv_6= 'actions' ( ( ruleQualifiedName ) ) (otherlv_8= ',' ( ( ruleQualifiedName ) ) )* ) )* otherlv_10= '}' )
            {
            // InternalRsamlText.g:2803:2: ( () otherlv_1= 'activity' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | this_RealTime_5= ruleRealTime[$current] | (otherlv_6= 'actions' ( ( ruleQualifiedName ) ) (otherlv_8= ',' ( ( ruleQualifiedName ) ) )* ) )* otherlv_10= '}' )
            // InternalRsamlText.g:2804:3: () otherlv_1= 'activity' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | this_RealTime_5= ruleRealTime[$current] | (otherlv_6= 'actions' ( ( ruleQualifiedName ) ) (otherlv_8= ',' ( ( ruleQualifiedName ) ) )* ) )* otherlv_10= '}'
            {
            // InternalRsamlText.g:2804:3: ()
            // InternalRsamlText.g:2805:4: 
            {

            				current = forceCreateModelElement(
            					grammarAccess.getActivityAccess().getActivityAction_0(),
            					current);
            			

            }

            otherlv_1=(Token)match(input,59,FOLLOW_3); 

            			newLeafNode(otherlv_1, grammarAccess.getActivityAccess().getActivityKeyword_1());
            		
            // InternalRsamlText.g:2815:3: ( (lv_name_2_0= ruleName ) )?
            int alt35=2;
            int LA35_0 = input.LA(1);

            if ( ((LA35_0>=RULE_STRING && LA35_0<=RULE_ID)||LA35_0==11||(LA35_0>=13 && LA35_0<=16)||(LA35_0>=18 && LA35_0<=29)||(LA35_0>=31 && LA35_0<=44)||(LA35_0>=46 && LA35_0<=80)||(LA35_0>=82 && LA35_0<=118)) ) {
                alt35=1;
            }
            switch (alt35) {
                case 1 :
                    // InternalRsamlText.g:2816:4: (lv_name_2_0= ruleName )
                    {
                    // InternalRsamlText.g:2816:4: (lv_name_2_0= ruleName )
                    // InternalRsamlText.g:2817:5: lv_name_2_0= ruleName
                    {

                    					newCompositeNode(grammarAccess.getActivityAccess().getNameNameParserRuleCall_2_0());
                    				
                    pushFollow(FOLLOW_4);
                    lv_name_2_0=ruleName();

                    state._fsp--;


                    					if (current==null) {
                    						current = createModelElementForParent(grammarAccess.getActivityRule());
                    					}
                    					set(
                    						current,
                    						"name",
                    						lv_name_2_0,
                    						"org.rsaml.text.RsamlText.Name");
                    					afterParserOrEnumRuleCall();
                    				

                    }


                    }
                    break;

            }

            otherlv_3=(Token)match(input,12,FOLLOW_34); 

            			newLeafNode(otherlv_3, grammarAccess.getActivityAccess().getLeftCurlyBracketKeyword_3());
            		
            // InternalRsamlText.g:2838:3: (this_Described_4= ruleDescribed[$current] | this_RealTime_5= ruleRealTime[$current] | (otherlv_6= 'actions' ( ( ruleQualifiedName ) ) (otherlv_8= ',' ( ( ruleQualifiedName ) ) )* ) )*
            loop37:
            do {
                int alt37=4;
                switch ( input.LA(1) ) {
                case 18:
                    {
                    alt37=1;
                    }
                    break;
                case 19:
                case 20:
                case 21:
                case 22:
                case 23:
                case 24:
                    {
                    alt37=2;
                    }
                    break;
                case 60:
                    {
                    alt37=3;
                    }
                    break;

                }

                switch (alt37) {
            	case 1 :
            	    // InternalRsamlText.g:2839:4: this_Described_4= ruleDescribed[$current]
            	    {

            	    				if (current==null) {
            	    					current = createModelElement(grammarAccess.getActivityRule());
            	    				}
            	    				newCompositeNode(grammarAccess.getActivityAccess().getDescribedParserRuleCall_4_0());
            	    			
            	    pushFollow(FOLLOW_34);
            	    this_Described_4=ruleDescribed(current);

            	    state._fsp--;


            	    				current = this_Described_4;
            	    				afterParserOrEnumRuleCall();
            	    			

            	    }
            	    break;
            	case 2 :
            	    // InternalRsamlText.g:2851:4: this_RealTime_5= ruleRealTime[$current]
            	    {

            	    				if (current==null) {
            	    					current = createModelElement(grammarAccess.getActivityRule());
            	    				}
            	    				newCompositeNode(grammarAccess.getActivityAccess().getRealTimeParserRuleCall_4_1());
            	    			
            	    pushFollow(FOLLOW_34);
            	    this_RealTime_5=ruleRealTime(current);

            	    state._fsp--;


            	    				current = this_RealTime_5;
            	    				afterParserOrEnumRuleCall();
            	    			

            	    }
            	    break;
            	case 3 :
            	    // InternalRsamlText.g:2863:4: (otherlv_6= 'actions' ( ( ruleQualifiedName ) ) (otherlv_8= ',' ( ( ruleQualifiedName ) ) )* )
            	    {
            	    // InternalRsamlText.g:2863:4: (otherlv_6= 'actions' ( ( ruleQualifiedName ) ) (otherlv_8= ',' ( ( ruleQualifiedName ) ) )* )
            	    // InternalRsamlText.g:2864:5: otherlv_6= 'actions' ( ( ruleQualifiedName ) ) (otherlv_8= ',' ( ( ruleQualifiedName ) ) )*
            	    {
            	    otherlv_6=(Token)match(input,60,FOLLOW_17); 

            	    					newLeafNode(otherlv_6, grammarAccess.getActivityAccess().getActionsKeyword_4_2_0());
            	    				
            	    // InternalRsamlText.g:2868:5: ( ( ruleQualifiedName ) )
            	    // InternalRsamlText.g:2869:6: ( ruleQualifiedName )
            	    {
            	    // InternalRsamlText.g:2869:6: ( ruleQualifiedName )
            	    // InternalRsamlText.g:2870:7: ruleQualifiedName
            	    {

            	    							if (current==null) {
            	    								current = createModelElement(grammarAccess.getActivityRule());
            	    							}
            	    						

            	    							newCompositeNode(grammarAccess.getActivityAccess().getActionsActionCrossReference_4_2_1_0());
            	    						
            	    pushFollow(FOLLOW_35);
            	    ruleQualifiedName();

            	    state._fsp--;


            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }

            	    // InternalRsamlText.g:2884:5: (otherlv_8= ',' ( ( ruleQualifiedName ) ) )*
            	    loop36:
            	    do {
            	        int alt36=2;
            	        int LA36_0 = input.LA(1);

            	        if ( (LA36_0==30) ) {
            	            alt36=1;
            	        }


            	        switch (alt36) {
            	    	case 1 :
            	    	    // InternalRsamlText.g:2885:6: otherlv_8= ',' ( ( ruleQualifiedName ) )
            	    	    {
            	    	    otherlv_8=(Token)match(input,30,FOLLOW_17); 

            	    	    						newLeafNode(otherlv_8, grammarAccess.getActivityAccess().getCommaKeyword_4_2_2_0());
            	    	    					
            	    	    // InternalRsamlText.g:2889:6: ( ( ruleQualifiedName ) )
            	    	    // InternalRsamlText.g:2890:7: ( ruleQualifiedName )
            	    	    {
            	    	    // InternalRsamlText.g:2890:7: ( ruleQualifiedName )
            	    	    // InternalRsamlText.g:2891:8: ruleQualifiedName
            	    	    {

            	    	    								if (current==null) {
            	    	    									current = createModelElement(grammarAccess.getActivityRule());
            	    	    								}
            	    	    							

            	    	    								newCompositeNode(grammarAccess.getActivityAccess().getActionsActionCrossReference_4_2_2_1_0());
            	    	    							
            	    	    pushFollow(FOLLOW_35);
            	    	    ruleQualifiedName();

            	    	    state._fsp--;


            	    	    								afterParserOrEnumRuleCall();
            	    	    							

            	    	    }


            	    	    }


            	    	    }
            	    	    break;

            	    	default :
            	    	    break loop36;
            	        }
            	    } while (true);


            	    }


            	    }
            	    break;

            	default :
            	    break loop37;
                }
            } while (true);

            otherlv_10=(Token)match(input,17,FOLLOW_2); 

            			newLeafNode(otherlv_10, grammarAccess.getActivityAccess().getRightCurlyBracketKeyword_5());
            		

            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "ruleActivity"


    // $ANTLR start "entryRuleSupervisor"
    // InternalRsamlText.g:2916:1: entryRuleSupervisor returns [EObject current=null] : iv_ruleSupervisor= ruleSupervisor EOF ;
    public final EObject entryRuleSupervisor() throws RecognitionException {
        EObject current = null;

        EObject iv_ruleSupervisor = null;


        try {
            // InternalRsamlText.g:2916:51: (iv_ruleSupervisor= ruleSupervisor EOF )
            // InternalRsamlText.g:2917:2: iv_ruleSupervisor= ruleSupervisor EOF
            {
             newCompositeNode(grammarAccess.getSupervisorRule()); 
            pushFollow(FOLLOW_1);
            iv_ruleSupervisor=ruleSupervisor();

            state._fsp--;

             current =iv_ruleSupervisor; 
            match(input,EOF,FOLLOW_2); 

            }

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "entryRuleSupervisor"


    // $ANTLR start "ruleSupervisor"
    // InternalRsamlText.g:2923:1: ruleSupervisor returns [EObject current=null] : ( () otherlv_1= 'supervisor' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'plans' ( ( ruleQualifiedName ) ) (otherlv_7= ',' ( ( ruleQualifiedName ) ) )* ) | (otherlv_9= 'realisedBy' ( ( ruleQualifiedName ) ) ) )* otherlv_11= '}' ) ;
    public final EObject ruleSupervisor() throws RecognitionException {
        EObject current = null;

        Token otherlv_1=null;
        Token otherlv_3=null;
        Token otherlv_5=null;
        Token otherlv_7=null;
        Token otherlv_9=null;
        Token otherlv_11=null;
        AntlrDatatypeRuleToken lv_name_2_0 = null;

        EObject this_Described_4 = null;



        	enterRule();

        try {
            // InternalRsamlText.g:2929:2: ( ( () otherlv_1= 'supervisor' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'plans' ( ( ruleQualifiedName ) ) (otherlv_7= ',' ( ( ruleQualifiedName ) ) )* ) | (otherlv_9= 'realisedBy' ( ( ruleQualifiedName ) ) ) )* otherlv_11= '}' ) )
            // InternalRsamlText.g:2930:2: ( () otherlv_1= 'supervisor' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'plans' ( ( ruleQualifiedName ) ) (otherlv_7= ',' ( ( ruleQualifiedName ) ) )* ) | (otherlv_9= 'realisedBy' ( ( ruleQualifiedName ) ) ) )* otherlv_11= '}' )
            {
            // InternalRsamlText.g:2930:2: ( () otherlv_1= 'supervisor' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'plans' ( ( ruleQualifiedName ) ) (otherlv_7= ',' ( ( ruleQualifiedName ) ) )* ) | (otherlv_9= 'realisedBy' ( ( ruleQualifiedName ) ) ) )* otherlv_11= '}' )
            // InternalRsamlText.g:2931:3: () otherlv_1= 'supervisor' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'plans' ( ( ruleQualifiedName ) ) (otherlv_7= ',' ( ( ruleQualifiedName ) ) )* ) | (otherlv_9= 'realisedBy' ( ( ruleQualifiedName ) ) ) )* otherlv_11= '}'
            {
            // InternalRsamlText.g:2931:3: ()
            // InternalRsamlText.g:2932:4: 
            {

            				current = forceCreateModelElement(
            					grammarAccess.getSupervisorAccess().getSupervisorAction_0(),
            					current);
            			

            }

            otherlv_1=(Token)match(input,61,FOLLOW_3); 

            			newLeafNode(otherlv_1, grammarAccess.getSupervisorAccess().getSupervisorKeyword_1());
            		
            // InternalRsamlText.g:2942:3: ( (lv_name_2_0= ruleName ) )?
            int alt38=2;
            int LA38_0 = input.LA(1);

            if ( ((LA38_0>=RULE_STRING && LA38_0<=RULE_ID)||LA38_0==11||(LA38_0>=13 && LA38_0<=16)||(LA38_0>=18 && LA38_0<=29)||(LA38_0>=31 && LA38_0<=44)||(LA38_0>=46 && LA38_0<=80)||(LA38_0>=82 && LA38_0<=118)) ) {
                alt38=1;
            }
            switch (alt38) {
                case 1 :
                    // InternalRsamlText.g:2943:4: (lv_name_2_0= ruleName )
                    {
                    // InternalRsamlText.g:2943:4: (lv_name_2_0= ruleName )
                    // InternalRsamlText.g:2944:5: lv_name_2_0= ruleName
                    {

                    					newCompositeNode(grammarAccess.getSupervisorAccess().getNameNameParserRuleCall_2_0());
                    				
                    pushFollow(FOLLOW_4);
                    lv_name_2_0=ruleName();

                    state._fsp--;


                    					if (current==null) {
                    						current = createModelElementForParent(grammarAccess.getSupervisorRule());
                    					}
                    					set(
                    						current,
                    						"name",
                    						lv_name_2_0,
                    						"org.rsaml.text.RsamlText.Name");
                    					afterParserOrEnumRuleCall();
                    				

                    }


                    }
                    break;

            }

            otherlv_3=(Token)match(input,12,FOLLOW_36); 

            			newLeafNode(otherlv_3, grammarAccess.getSupervisorAccess().getLeftCurlyBracketKeyword_3());
            		
            // InternalRsamlText.g:2965:3: (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'plans' ( ( ruleQualifiedName ) ) (otherlv_7= ',' ( ( ruleQualifiedName ) ) )* ) | (otherlv_9= 'realisedBy' ( ( ruleQualifiedName ) ) ) )*
            loop40:
            do {
                int alt40=4;
                switch ( input.LA(1) ) {
                case 18:
                    {
                    alt40=1;
                    }
                    break;
                case 62:
                    {
                    alt40=2;
                    }
                    break;
                case 63:
                    {
                    alt40=3;
                    }
                    break;

                }

                switch (alt40) {
            	case 1 :
            	    // InternalRsamlText.g:2966:4: this_Described_4= ruleDescribed[$current]
            	    {

            	    				if (current==null) {
            	    					current = createModelElement(grammarAccess.getSupervisorRule());
            	    				}
            	    				newCompositeNode(grammarAccess.getSupervisorAccess().getDescribedParserRuleCall_4_0());
            	    			
            	    pushFollow(FOLLOW_36);
            	    this_Described_4=ruleDescribed(current);

            	    state._fsp--;


            	    				current = this_Described_4;
            	    				afterParserOrEnumRuleCall();
            	    			

            	    }
            	    break;
            	case 2 :
            	    // InternalRsamlText.g:2978:4: (otherlv_5= 'plans' ( ( ruleQualifiedName ) ) (otherlv_7= ',' ( ( ruleQualifiedName ) ) )* )
            	    {
            	    // InternalRsamlText.g:2978:4: (otherlv_5= 'plans' ( ( ruleQualifiedName ) ) (otherlv_7= ',' ( ( ruleQualifiedName ) ) )* )
            	    // InternalRsamlText.g:2979:5: otherlv_5= 'plans' ( ( ruleQualifiedName ) ) (otherlv_7= ',' ( ( ruleQualifiedName ) ) )*
            	    {
            	    otherlv_5=(Token)match(input,62,FOLLOW_17); 

            	    					newLeafNode(otherlv_5, grammarAccess.getSupervisorAccess().getPlansKeyword_4_1_0());
            	    				
            	    // InternalRsamlText.g:2983:5: ( ( ruleQualifiedName ) )
            	    // InternalRsamlText.g:2984:6: ( ruleQualifiedName )
            	    {
            	    // InternalRsamlText.g:2984:6: ( ruleQualifiedName )
            	    // InternalRsamlText.g:2985:7: ruleQualifiedName
            	    {

            	    							if (current==null) {
            	    								current = createModelElement(grammarAccess.getSupervisorRule());
            	    							}
            	    						

            	    							newCompositeNode(grammarAccess.getSupervisorAccess().getPlansPlanCrossReference_4_1_1_0());
            	    						
            	    pushFollow(FOLLOW_37);
            	    ruleQualifiedName();

            	    state._fsp--;


            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }

            	    // InternalRsamlText.g:2999:5: (otherlv_7= ',' ( ( ruleQualifiedName ) ) )*
            	    loop39:
            	    do {
            	        int alt39=2;
            	        int LA39_0 = input.LA(1);

            	        if ( (LA39_0==30) ) {
            	            alt39=1;
            	        }


            	        switch (alt39) {
            	    	case 1 :
            	    	    // InternalRsamlText.g:3000:6: otherlv_7= ',' ( ( ruleQualifiedName ) )
            	    	    {
            	    	    otherlv_7=(Token)match(input,30,FOLLOW_17); 

            	    	    						newLeafNode(otherlv_7, grammarAccess.getSupervisorAccess().getCommaKeyword_4_1_2_0());
            	    	    					
            	    	    // InternalRsamlText.g:3004:6: ( ( ruleQualifiedName ) )
            	    	    // InternalRsamlText.g:3005:7: ( ruleQualifiedName )
            	    	    {
            	    	    // InternalRsamlText.g:3005:7: ( ruleQualifiedName )
            	    	    // InternalRsamlText.g:3006:8: ruleQualifiedName
            	    	    {

            	    	    								if (current==null) {
            	    	    									current = createModelElement(grammarAccess.getSupervisorRule());
            	    	    								}
            	    	    							

            	    	    								newCompositeNode(grammarAccess.getSupervisorAccess().getPlansPlanCrossReference_4_1_2_1_0());
            	    	    							
            	    	    pushFollow(FOLLOW_37);
            	    	    ruleQualifiedName();

            	    	    state._fsp--;


            	    	    								afterParserOrEnumRuleCall();
            	    	    							

            	    	    }


            	    	    }


            	    	    }
            	    	    break;

            	    	default :
            	    	    break loop39;
            	        }
            	    } while (true);


            	    }


            	    }
            	    break;
            	case 3 :
            	    // InternalRsamlText.g:3023:4: (otherlv_9= 'realisedBy' ( ( ruleQualifiedName ) ) )
            	    {
            	    // InternalRsamlText.g:3023:4: (otherlv_9= 'realisedBy' ( ( ruleQualifiedName ) ) )
            	    // InternalRsamlText.g:3024:5: otherlv_9= 'realisedBy' ( ( ruleQualifiedName ) )
            	    {
            	    otherlv_9=(Token)match(input,63,FOLLOW_17); 

            	    					newLeafNode(otherlv_9, grammarAccess.getSupervisorAccess().getRealisedByKeyword_4_2_0());
            	    				
            	    // InternalRsamlText.g:3028:5: ( ( ruleQualifiedName ) )
            	    // InternalRsamlText.g:3029:6: ( ruleQualifiedName )
            	    {
            	    // InternalRsamlText.g:3029:6: ( ruleQualifiedName )
            	    // InternalRsamlText.g:3030:7: ruleQualifiedName
            	    {

            	    							if (current==null) {
            	    								current = createModelElement(grammarAccess.getSupervisorRule());
            	    							}
            	    						

            	    							newCompositeNode(grammarAccess.getSupervisorAccess().getRealisedByModuleCrossReference_4_2_1_0());
            	    						
            	    pushFollow(FOLLOW_36);
            	    ruleQualifiedName();

            	    state._fsp--;


            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;

            	default :
            	    break loop40;
                }
            } while (true);

            otherlv_11=(Token)match(input,17,FOLLOW_2); 

            			newLeafNode(otherlv_11, grammarAccess.getSupervisorAccess().getRightCurlyBracketKeyword_5());
            		

            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "ruleSupervisor"


    // $ANTLR start "entryRuleOrder"
    // InternalRsamlText.g:3054:1: entryRuleOrder returns [EObject current=null] : iv_ruleOrder= ruleOrder EOF ;
    public final EObject entryRuleOrder() throws RecognitionException {
        EObject current = null;

        EObject iv_ruleOrder = null;


        try {
            // InternalRsamlText.g:3054:46: (iv_ruleOrder= ruleOrder EOF )
            // InternalRsamlText.g:3055:2: iv_ruleOrder= ruleOrder EOF
            {
             newCompositeNode(grammarAccess.getOrderRule()); 
            pushFollow(FOLLOW_1);
            iv_ruleOrder=ruleOrder();

            state._fsp--;

             current =iv_ruleOrder; 
            match(input,EOF,FOLLOW_2); 

            }

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "entryRuleOrder"


    // $ANTLR start "ruleOrder"
    // InternalRsamlText.g:3061:1: ruleOrder returns [EObject current=null] : ( () otherlv_1= 'order' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'issuer' ( (lv_issuer_6_0= RULE_STRING ) ) ) | (otherlv_7= 'receiver' ( ( ruleQualifiedName ) ) ) | (otherlv_9= 'requests' ( ( ruleQualifiedName ) ) ) )* otherlv_11= '}' ) ;
    public final EObject ruleOrder() throws RecognitionException {
        EObject current = null;

        Token otherlv_1=null;
        Token otherlv_3=null;
        Token otherlv_5=null;
        Token lv_issuer_6_0=null;
        Token otherlv_7=null;
        Token otherlv_9=null;
        Token otherlv_11=null;
        AntlrDatatypeRuleToken lv_name_2_0 = null;

        EObject this_Described_4 = null;



        	enterRule();

        try {
            // InternalRsamlText.g:3067:2: ( ( () otherlv_1= 'order' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'issuer' ( (lv_issuer_6_0= RULE_STRING ) ) ) | (otherlv_7= 'receiver' ( ( ruleQualifiedName ) ) ) | (otherlv_9= 'requests' ( ( ruleQualifiedName ) ) ) )* otherlv_11= '}' ) )
            // InternalRsamlText.g:3068:2: ( () otherlv_1= 'order' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'issuer' ( (lv_issuer_6_0= RULE_STRING ) ) ) | (otherlv_7= 'receiver' ( ( ruleQualifiedName ) ) ) | (otherlv_9= 'requests' ( ( ruleQualifiedName ) ) ) )* otherlv_11= '}' )
            {
            // InternalRsamlText.g:3068:2: ( () otherlv_1= 'order' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'issuer' ( (lv_issuer_6_0= RULE_STRING ) ) ) | (otherlv_7= 'receiver' ( ( ruleQualifiedName ) ) ) | (otherlv_9= 'requests' ( ( ruleQualifiedName ) ) ) )* otherlv_11= '}' )
            // InternalRsamlText.g:3069:3: () otherlv_1= 'order' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'issuer' ( (lv_issuer_6_0= RULE_STRING ) ) ) | (otherlv_7= 'receiver' ( ( ruleQualifiedName ) ) ) | (otherlv_9= 'requests' ( ( ruleQualifiedName ) ) ) )* otherlv_11= '}'
            {
            // InternalRsamlText.g:3069:3: ()
            // InternalRsamlText.g:3070:4: 
            {

            				current = forceCreateModelElement(
            					grammarAccess.getOrderAccess().getOrderAction_0(),
            					current);
            			

            }

            otherlv_1=(Token)match(input,64,FOLLOW_3); 

            			newLeafNode(otherlv_1, grammarAccess.getOrderAccess().getOrderKeyword_1());
            		
            // InternalRsamlText.g:3080:3: ( (lv_name_2_0= ruleName ) )?
            int alt41=2;
            int LA41_0 = input.LA(1);

            if ( ((LA41_0>=RULE_STRING && LA41_0<=RULE_ID)||LA41_0==11||(LA41_0>=13 && LA41_0<=16)||(LA41_0>=18 && LA41_0<=29)||(LA41_0>=31 && LA41_0<=44)||(LA41_0>=46 && LA41_0<=80)||(LA41_0>=82 && LA41_0<=118)) ) {
                alt41=1;
            }
            switch (alt41) {
                case 1 :
                    // InternalRsamlText.g:3081:4: (lv_name_2_0= ruleName )
                    {
                    // InternalRsamlText.g:3081:4: (lv_name_2_0= ruleName )
                    // InternalRsamlText.g:3082:5: lv_name_2_0= ruleName
                    {

                    					newCompositeNode(grammarAccess.getOrderAccess().getNameNameParserRuleCall_2_0());
                    				
                    pushFollow(FOLLOW_4);
                    lv_name_2_0=ruleName();

                    state._fsp--;


                    					if (current==null) {
                    						current = createModelElementForParent(grammarAccess.getOrderRule());
                    					}
                    					set(
                    						current,
                    						"name",
                    						lv_name_2_0,
                    						"org.rsaml.text.RsamlText.Name");
                    					afterParserOrEnumRuleCall();
                    				

                    }


                    }
                    break;

            }

            otherlv_3=(Token)match(input,12,FOLLOW_38); 

            			newLeafNode(otherlv_3, grammarAccess.getOrderAccess().getLeftCurlyBracketKeyword_3());
            		
            // InternalRsamlText.g:3103:3: (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'issuer' ( (lv_issuer_6_0= RULE_STRING ) ) ) | (otherlv_7= 'receiver' ( ( ruleQualifiedName ) ) ) | (otherlv_9= 'requests' ( ( ruleQualifiedName ) ) ) )*
            loop42:
            do {
                int alt42=5;
                switch ( input.LA(1) ) {
                case 18:
                    {
                    alt42=1;
                    }
                    break;
                case 65:
                    {
                    alt42=2;
                    }
                    break;
                case 66:
                    {
                    alt42=3;
                    }
                    break;
                case 67:
                    {
                    alt42=4;
                    }
                    break;

                }

                switch (alt42) {
            	case 1 :
            	    // InternalRsamlText.g:3104:4: this_Described_4= ruleDescribed[$current]
            	    {

            	    				if (current==null) {
            	    					current = createModelElement(grammarAccess.getOrderRule());
            	    				}
            	    				newCompositeNode(grammarAccess.getOrderAccess().getDescribedParserRuleCall_4_0());
            	    			
            	    pushFollow(FOLLOW_38);
            	    this_Described_4=ruleDescribed(current);

            	    state._fsp--;


            	    				current = this_Described_4;
            	    				afterParserOrEnumRuleCall();
            	    			

            	    }
            	    break;
            	case 2 :
            	    // InternalRsamlText.g:3116:4: (otherlv_5= 'issuer' ( (lv_issuer_6_0= RULE_STRING ) ) )
            	    {
            	    // InternalRsamlText.g:3116:4: (otherlv_5= 'issuer' ( (lv_issuer_6_0= RULE_STRING ) ) )
            	    // InternalRsamlText.g:3117:5: otherlv_5= 'issuer' ( (lv_issuer_6_0= RULE_STRING ) )
            	    {
            	    otherlv_5=(Token)match(input,65,FOLLOW_10); 

            	    					newLeafNode(otherlv_5, grammarAccess.getOrderAccess().getIssuerKeyword_4_1_0());
            	    				
            	    // InternalRsamlText.g:3121:5: ( (lv_issuer_6_0= RULE_STRING ) )
            	    // InternalRsamlText.g:3122:6: (lv_issuer_6_0= RULE_STRING )
            	    {
            	    // InternalRsamlText.g:3122:6: (lv_issuer_6_0= RULE_STRING )
            	    // InternalRsamlText.g:3123:7: lv_issuer_6_0= RULE_STRING
            	    {
            	    lv_issuer_6_0=(Token)match(input,RULE_STRING,FOLLOW_38); 

            	    							newLeafNode(lv_issuer_6_0, grammarAccess.getOrderAccess().getIssuerSTRINGTerminalRuleCall_4_1_1_0());
            	    						

            	    							if (current==null) {
            	    								current = createModelElement(grammarAccess.getOrderRule());
            	    							}
            	    							setWithLastConsumed(
            	    								current,
            	    								"issuer",
            	    								lv_issuer_6_0,
            	    								"org.rsaml.text.RsamlText.STRING");
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;
            	case 3 :
            	    // InternalRsamlText.g:3141:4: (otherlv_7= 'receiver' ( ( ruleQualifiedName ) ) )
            	    {
            	    // InternalRsamlText.g:3141:4: (otherlv_7= 'receiver' ( ( ruleQualifiedName ) ) )
            	    // InternalRsamlText.g:3142:5: otherlv_7= 'receiver' ( ( ruleQualifiedName ) )
            	    {
            	    otherlv_7=(Token)match(input,66,FOLLOW_17); 

            	    					newLeafNode(otherlv_7, grammarAccess.getOrderAccess().getReceiverKeyword_4_2_0());
            	    				
            	    // InternalRsamlText.g:3146:5: ( ( ruleQualifiedName ) )
            	    // InternalRsamlText.g:3147:6: ( ruleQualifiedName )
            	    {
            	    // InternalRsamlText.g:3147:6: ( ruleQualifiedName )
            	    // InternalRsamlText.g:3148:7: ruleQualifiedName
            	    {

            	    							if (current==null) {
            	    								current = createModelElement(grammarAccess.getOrderRule());
            	    							}
            	    						

            	    							newCompositeNode(grammarAccess.getOrderAccess().getReceiverModuleCrossReference_4_2_1_0());
            	    						
            	    pushFollow(FOLLOW_38);
            	    ruleQualifiedName();

            	    state._fsp--;


            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;
            	case 4 :
            	    // InternalRsamlText.g:3164:4: (otherlv_9= 'requests' ( ( ruleQualifiedName ) ) )
            	    {
            	    // InternalRsamlText.g:3164:4: (otherlv_9= 'requests' ( ( ruleQualifiedName ) ) )
            	    // InternalRsamlText.g:3165:5: otherlv_9= 'requests' ( ( ruleQualifiedName ) )
            	    {
            	    otherlv_9=(Token)match(input,67,FOLLOW_17); 

            	    					newLeafNode(otherlv_9, grammarAccess.getOrderAccess().getRequestsKeyword_4_3_0());
            	    				
            	    // InternalRsamlText.g:3169:5: ( ( ruleQualifiedName ) )
            	    // InternalRsamlText.g:3170:6: ( ruleQualifiedName )
            	    {
            	    // InternalRsamlText.g:3170:6: ( ruleQualifiedName )
            	    // InternalRsamlText.g:3171:7: ruleQualifiedName
            	    {

            	    							if (current==null) {
            	    								current = createModelElement(grammarAccess.getOrderRule());
            	    							}
            	    						

            	    							newCompositeNode(grammarAccess.getOrderAccess().getRequestsActivityCrossReference_4_3_1_0());
            	    						
            	    pushFollow(FOLLOW_38);
            	    ruleQualifiedName();

            	    state._fsp--;


            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;

            	default :
            	    break loop42;
                }
            } while (true);

            otherlv_11=(Token)match(input,17,FOLLOW_2); 

            			newLeafNode(otherlv_11, grammarAccess.getOrderAccess().getRightCurlyBracketKeyword_5());
            		

            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "ruleOrder"


    // $ANTLR start "entryRuleDatabase"
    // InternalRsamlText.g:3195:1: entryRuleDatabase returns [EObject current=null] : iv_ruleDatabase= ruleDatabase EOF ;
    public final EObject entryRuleDatabase() throws RecognitionException {
        EObject current = null;

        EObject iv_ruleDatabase = null;


        try {
            // InternalRsamlText.g:3195:49: (iv_ruleDatabase= ruleDatabase EOF )
            // InternalRsamlText.g:3196:2: iv_ruleDatabase= ruleDatabase EOF
            {
             newCompositeNode(grammarAccess.getDatabaseRule()); 
            pushFollow(FOLLOW_1);
            iv_ruleDatabase=ruleDatabase();

            state._fsp--;

             current =iv_ruleDatabase; 
            match(input,EOF,FOLLOW_2); 

            }

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "entryRuleDatabase"


    // $ANTLR start "ruleDatabase"
    // InternalRsamlText.g:3202:1: ruleDatabase returns [EObject current=null] : ( () otherlv_1= 'database' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | ( (lv_knowledge_5_0= ruleKnowledge ) ) )* otherlv_6= '}' ) ;
    public final EObject ruleDatabase() throws RecognitionException {
        EObject current = null;

        Token otherlv_1=null;
        Token otherlv_3=null;
        Token otherlv_6=null;
        AntlrDatatypeRuleToken lv_name_2_0 = null;

        EObject this_Described_4 = null;

        EObject lv_knowledge_5_0 = null;



        	enterRule();

        try {
            // InternalRsamlText.g:3208:2: ( ( () otherlv_1= 'database' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | ( (lv_knowledge_5_0= ruleKnowledge ) ) )* otherlv_6= '}' ) )
            // InternalRsamlText.g:3209:2: ( () otherlv_1= 'database' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | ( (lv_knowledge_5_0= ruleKnowledge ) ) )* otherlv_6= '}' )
            {
            // InternalRsamlText.g:3209:2: ( () otherlv_1= 'database' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | ( (lv_knowledge_5_0= ruleKnowledge ) ) )* otherlv_6= '}' )
            // InternalRsamlText.g:3210:3: () otherlv_1= 'database' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | ( (lv_knowledge_5_0= ruleKnowledge ) ) )* otherlv_6= '}'
            {
            // InternalRsamlText.g:3210:3: ()
            // InternalRsamlText.g:3211:4: 
            {

            				current = forceCreateModelElement(
            					grammarAccess.getDatabaseAccess().getDatabaseAction_0(),
            					current);
            			

            }

            otherlv_1=(Token)match(input,68,FOLLOW_3); 

            			newLeafNode(otherlv_1, grammarAccess.getDatabaseAccess().getDatabaseKeyword_1());
            		
            // InternalRsamlText.g:3221:3: ( (lv_name_2_0= ruleName ) )?
            int alt43=2;
            int LA43_0 = input.LA(1);

            if ( ((LA43_0>=RULE_STRING && LA43_0<=RULE_ID)||LA43_0==11||(LA43_0>=13 && LA43_0<=16)||(LA43_0>=18 && LA43_0<=29)||(LA43_0>=31 && LA43_0<=44)||(LA43_0>=46 && LA43_0<=80)||(LA43_0>=82 && LA43_0<=118)) ) {
                alt43=1;
            }
            switch (alt43) {
                case 1 :
                    // InternalRsamlText.g:3222:4: (lv_name_2_0= ruleName )
                    {
                    // InternalRsamlText.g:3222:4: (lv_name_2_0= ruleName )
                    // InternalRsamlText.g:3223:5: lv_name_2_0= ruleName
                    {

                    					newCompositeNode(grammarAccess.getDatabaseAccess().getNameNameParserRuleCall_2_0());
                    				
                    pushFollow(FOLLOW_4);
                    lv_name_2_0=ruleName();

                    state._fsp--;


                    					if (current==null) {
                    						current = createModelElementForParent(grammarAccess.getDatabaseRule());
                    					}
                    					set(
                    						current,
                    						"name",
                    						lv_name_2_0,
                    						"org.rsaml.text.RsamlText.Name");
                    					afterParserOrEnumRuleCall();
                    				

                    }


                    }
                    break;

            }

            otherlv_3=(Token)match(input,12,FOLLOW_39); 

            			newLeafNode(otherlv_3, grammarAccess.getDatabaseAccess().getLeftCurlyBracketKeyword_3());
            		
            // InternalRsamlText.g:3244:3: (this_Described_4= ruleDescribed[$current] | ( (lv_knowledge_5_0= ruleKnowledge ) ) )*
            loop44:
            do {
                int alt44=3;
                int LA44_0 = input.LA(1);

                if ( (LA44_0==18) ) {
                    alt44=1;
                }
                else if ( (LA44_0==69) ) {
                    alt44=2;
                }


                switch (alt44) {
            	case 1 :
            	    // InternalRsamlText.g:3245:4: this_Described_4= ruleDescribed[$current]
            	    {

            	    				if (current==null) {
            	    					current = createModelElement(grammarAccess.getDatabaseRule());
            	    				}
            	    				newCompositeNode(grammarAccess.getDatabaseAccess().getDescribedParserRuleCall_4_0());
            	    			
            	    pushFollow(FOLLOW_39);
            	    this_Described_4=ruleDescribed(current);

            	    state._fsp--;


            	    				current = this_Described_4;
            	    				afterParserOrEnumRuleCall();
            	    			

            	    }
            	    break;
            	case 2 :
            	    // InternalRsamlText.g:3257:4: ( (lv_knowledge_5_0= ruleKnowledge ) )
            	    {
            	    // InternalRsamlText.g:3257:4: ( (lv_knowledge_5_0= ruleKnowledge ) )
            	    // InternalRsamlText.g:3258:5: (lv_knowledge_5_0= ruleKnowledge )
            	    {
            	    // InternalRsamlText.g:3258:5: (lv_knowledge_5_0= ruleKnowledge )
            	    // InternalRsamlText.g:3259:6: lv_knowledge_5_0= ruleKnowledge
            	    {

            	    						newCompositeNode(grammarAccess.getDatabaseAccess().getKnowledgeKnowledgeParserRuleCall_4_1_0());
            	    					
            	    pushFollow(FOLLOW_39);
            	    lv_knowledge_5_0=ruleKnowledge();

            	    state._fsp--;


            	    						if (current==null) {
            	    							current = createModelElementForParent(grammarAccess.getDatabaseRule());
            	    						}
            	    						add(
            	    							current,
            	    							"knowledge",
            	    							lv_knowledge_5_0,
            	    							"org.rsaml.text.RsamlText.Knowledge");
            	    						afterParserOrEnumRuleCall();
            	    					

            	    }


            	    }


            	    }
            	    break;

            	default :
            	    break loop44;
                }
            } while (true);

            otherlv_6=(Token)match(input,17,FOLLOW_2); 

            			newLeafNode(otherlv_6, grammarAccess.getDatabaseAccess().getRightCurlyBracketKeyword_5());
            		

            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "ruleDatabase"


    // $ANTLR start "entryRuleKnowledge"
    // InternalRsamlText.g:3285:1: entryRuleKnowledge returns [EObject current=null] : iv_ruleKnowledge= ruleKnowledge EOF ;
    public final EObject entryRuleKnowledge() throws RecognitionException {
        EObject current = null;

        EObject iv_ruleKnowledge = null;


        try {
            // InternalRsamlText.g:3285:50: (iv_ruleKnowledge= ruleKnowledge EOF )
            // InternalRsamlText.g:3286:2: iv_ruleKnowledge= ruleKnowledge EOF
            {
             newCompositeNode(grammarAccess.getKnowledgeRule()); 
            pushFollow(FOLLOW_1);
            iv_ruleKnowledge=ruleKnowledge();

            state._fsp--;

             current =iv_ruleKnowledge; 
            match(input,EOF,FOLLOW_2); 

            }

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "entryRuleKnowledge"


    // $ANTLR start "ruleKnowledge"
    // InternalRsamlText.g:3292:1: ruleKnowledge returns [EObject current=null] : ( () otherlv_1= 'knowledge' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'dataType' ( (lv_dataType_6_0= ruleDataType ) ) ) | (otherlv_7= 'usedBy' ( ( ruleQualifiedName ) ) (otherlv_9= ',' ( ( ruleQualifiedName ) ) )* ) )* otherlv_11= '}' ) ;
    public final EObject ruleKnowledge() throws RecognitionException {
        EObject current = null;

        Token otherlv_1=null;
        Token otherlv_3=null;
        Token otherlv_5=null;
        Token otherlv_7=null;
        Token otherlv_9=null;
        Token otherlv_11=null;
        AntlrDatatypeRuleToken lv_name_2_0 = null;

        EObject this_Described_4 = null;

        Enumerator lv_dataType_6_0 = null;



        	enterRule();

        try {
            // InternalRsamlText.g:3298:2: ( ( () otherlv_1= 'knowledge' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'dataType' ( (lv_dataType_6_0= ruleDataType ) ) ) | (otherlv_7= 'usedBy' ( ( ruleQualifiedName ) ) (otherlv_9= ',' ( ( ruleQualifiedName ) ) )* ) )* otherlv_11= '}' ) )
            // InternalRsamlText.g:3299:2: ( () otherlv_1= 'knowledge' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'dataType' ( (lv_dataType_6_0= ruleDataType ) ) ) | (otherlv_7= 'usedBy' ( ( ruleQualifiedName ) ) (otherlv_9= ',' ( ( ruleQualifiedName ) ) )* ) )* otherlv_11= '}' )
            {
            // InternalRsamlText.g:3299:2: ( () otherlv_1= 'knowledge' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'dataType' ( (lv_dataType_6_0= ruleDataType ) ) ) | (otherlv_7= 'usedBy' ( ( ruleQualifiedName ) ) (otherlv_9= ',' ( ( ruleQualifiedName ) ) )* ) )* otherlv_11= '}' )
            // InternalRsamlText.g:3300:3: () otherlv_1= 'knowledge' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'dataType' ( (lv_dataType_6_0= ruleDataType ) ) ) | (otherlv_7= 'usedBy' ( ( ruleQualifiedName ) ) (otherlv_9= ',' ( ( ruleQualifiedName ) ) )* ) )* otherlv_11= '}'
            {
            // InternalRsamlText.g:3300:3: ()
            // InternalRsamlText.g:3301:4: 
            {

            				current = forceCreateModelElement(
            					grammarAccess.getKnowledgeAccess().getKnowledgeAction_0(),
            					current);
            			

            }

            otherlv_1=(Token)match(input,69,FOLLOW_3); 

            			newLeafNode(otherlv_1, grammarAccess.getKnowledgeAccess().getKnowledgeKeyword_1());
            		
            // InternalRsamlText.g:3311:3: ( (lv_name_2_0= ruleName ) )?
            int alt45=2;
            int LA45_0 = input.LA(1);

            if ( ((LA45_0>=RULE_STRING && LA45_0<=RULE_ID)||LA45_0==11||(LA45_0>=13 && LA45_0<=16)||(LA45_0>=18 && LA45_0<=29)||(LA45_0>=31 && LA45_0<=44)||(LA45_0>=46 && LA45_0<=80)||(LA45_0>=82 && LA45_0<=118)) ) {
                alt45=1;
            }
            switch (alt45) {
                case 1 :
                    // InternalRsamlText.g:3312:4: (lv_name_2_0= ruleName )
                    {
                    // InternalRsamlText.g:3312:4: (lv_name_2_0= ruleName )
                    // InternalRsamlText.g:3313:5: lv_name_2_0= ruleName
                    {

                    					newCompositeNode(grammarAccess.getKnowledgeAccess().getNameNameParserRuleCall_2_0());
                    				
                    pushFollow(FOLLOW_4);
                    lv_name_2_0=ruleName();

                    state._fsp--;


                    					if (current==null) {
                    						current = createModelElementForParent(grammarAccess.getKnowledgeRule());
                    					}
                    					set(
                    						current,
                    						"name",
                    						lv_name_2_0,
                    						"org.rsaml.text.RsamlText.Name");
                    					afterParserOrEnumRuleCall();
                    				

                    }


                    }
                    break;

            }

            otherlv_3=(Token)match(input,12,FOLLOW_40); 

            			newLeafNode(otherlv_3, grammarAccess.getKnowledgeAccess().getLeftCurlyBracketKeyword_3());
            		
            // InternalRsamlText.g:3334:3: (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'dataType' ( (lv_dataType_6_0= ruleDataType ) ) ) | (otherlv_7= 'usedBy' ( ( ruleQualifiedName ) ) (otherlv_9= ',' ( ( ruleQualifiedName ) ) )* ) )*
            loop47:
            do {
                int alt47=4;
                switch ( input.LA(1) ) {
                case 18:
                    {
                    alt47=1;
                    }
                    break;
                case 41:
                    {
                    alt47=2;
                    }
                    break;
                case 70:
                    {
                    alt47=3;
                    }
                    break;

                }

                switch (alt47) {
            	case 1 :
            	    // InternalRsamlText.g:3335:4: this_Described_4= ruleDescribed[$current]
            	    {

            	    				if (current==null) {
            	    					current = createModelElement(grammarAccess.getKnowledgeRule());
            	    				}
            	    				newCompositeNode(grammarAccess.getKnowledgeAccess().getDescribedParserRuleCall_4_0());
            	    			
            	    pushFollow(FOLLOW_40);
            	    this_Described_4=ruleDescribed(current);

            	    state._fsp--;


            	    				current = this_Described_4;
            	    				afterParserOrEnumRuleCall();
            	    			

            	    }
            	    break;
            	case 2 :
            	    // InternalRsamlText.g:3347:4: (otherlv_5= 'dataType' ( (lv_dataType_6_0= ruleDataType ) ) )
            	    {
            	    // InternalRsamlText.g:3347:4: (otherlv_5= 'dataType' ( (lv_dataType_6_0= ruleDataType ) ) )
            	    // InternalRsamlText.g:3348:5: otherlv_5= 'dataType' ( (lv_dataType_6_0= ruleDataType ) )
            	    {
            	    otherlv_5=(Token)match(input,41,FOLLOW_24); 

            	    					newLeafNode(otherlv_5, grammarAccess.getKnowledgeAccess().getDataTypeKeyword_4_1_0());
            	    				
            	    // InternalRsamlText.g:3352:5: ( (lv_dataType_6_0= ruleDataType ) )
            	    // InternalRsamlText.g:3353:6: (lv_dataType_6_0= ruleDataType )
            	    {
            	    // InternalRsamlText.g:3353:6: (lv_dataType_6_0= ruleDataType )
            	    // InternalRsamlText.g:3354:7: lv_dataType_6_0= ruleDataType
            	    {

            	    							newCompositeNode(grammarAccess.getKnowledgeAccess().getDataTypeDataTypeEnumRuleCall_4_1_1_0());
            	    						
            	    pushFollow(FOLLOW_40);
            	    lv_dataType_6_0=ruleDataType();

            	    state._fsp--;


            	    							if (current==null) {
            	    								current = createModelElementForParent(grammarAccess.getKnowledgeRule());
            	    							}
            	    							set(
            	    								current,
            	    								"dataType",
            	    								lv_dataType_6_0,
            	    								"org.rsaml.text.RsamlText.DataType");
            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;
            	case 3 :
            	    // InternalRsamlText.g:3373:4: (otherlv_7= 'usedBy' ( ( ruleQualifiedName ) ) (otherlv_9= ',' ( ( ruleQualifiedName ) ) )* )
            	    {
            	    // InternalRsamlText.g:3373:4: (otherlv_7= 'usedBy' ( ( ruleQualifiedName ) ) (otherlv_9= ',' ( ( ruleQualifiedName ) ) )* )
            	    // InternalRsamlText.g:3374:5: otherlv_7= 'usedBy' ( ( ruleQualifiedName ) ) (otherlv_9= ',' ( ( ruleQualifiedName ) ) )*
            	    {
            	    otherlv_7=(Token)match(input,70,FOLLOW_17); 

            	    					newLeafNode(otherlv_7, grammarAccess.getKnowledgeAccess().getUsedByKeyword_4_2_0());
            	    				
            	    // InternalRsamlText.g:3378:5: ( ( ruleQualifiedName ) )
            	    // InternalRsamlText.g:3379:6: ( ruleQualifiedName )
            	    {
            	    // InternalRsamlText.g:3379:6: ( ruleQualifiedName )
            	    // InternalRsamlText.g:3380:7: ruleQualifiedName
            	    {

            	    							if (current==null) {
            	    								current = createModelElement(grammarAccess.getKnowledgeRule());
            	    							}
            	    						

            	    							newCompositeNode(grammarAccess.getKnowledgeAccess().getUsedByModuleCrossReference_4_2_1_0());
            	    						
            	    pushFollow(FOLLOW_41);
            	    ruleQualifiedName();

            	    state._fsp--;


            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }

            	    // InternalRsamlText.g:3394:5: (otherlv_9= ',' ( ( ruleQualifiedName ) ) )*
            	    loop46:
            	    do {
            	        int alt46=2;
            	        int LA46_0 = input.LA(1);

            	        if ( (LA46_0==30) ) {
            	            alt46=1;
            	        }


            	        switch (alt46) {
            	    	case 1 :
            	    	    // InternalRsamlText.g:3395:6: otherlv_9= ',' ( ( ruleQualifiedName ) )
            	    	    {
            	    	    otherlv_9=(Token)match(input,30,FOLLOW_17); 

            	    	    						newLeafNode(otherlv_9, grammarAccess.getKnowledgeAccess().getCommaKeyword_4_2_2_0());
            	    	    					
            	    	    // InternalRsamlText.g:3399:6: ( ( ruleQualifiedName ) )
            	    	    // InternalRsamlText.g:3400:7: ( ruleQualifiedName )
            	    	    {
            	    	    // InternalRsamlText.g:3400:7: ( ruleQualifiedName )
            	    	    // InternalRsamlText.g:3401:8: ruleQualifiedName
            	    	    {

            	    	    								if (current==null) {
            	    	    									current = createModelElement(grammarAccess.getKnowledgeRule());
            	    	    								}
            	    	    							

            	    	    								newCompositeNode(grammarAccess.getKnowledgeAccess().getUsedByModuleCrossReference_4_2_2_1_0());
            	    	    							
            	    	    pushFollow(FOLLOW_41);
            	    	    ruleQualifiedName();

            	    	    state._fsp--;


            	    	    								afterParserOrEnumRuleCall();
            	    	    							

            	    	    }


            	    	    }


            	    	    }
            	    	    break;

            	    	default :
            	    	    break loop46;
            	        }
            	    } while (true);


            	    }


            	    }
            	    break;

            	default :
            	    break loop47;
                }
            } while (true);

            otherlv_11=(Token)match(input,17,FOLLOW_2); 

            			newLeafNode(otherlv_11, grammarAccess.getKnowledgeAccess().getRightCurlyBracketKeyword_5());
            		

            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "ruleKnowledge"


    // $ANTLR start "entryRuleProcessor"
    // InternalRsamlText.g:3426:1: entryRuleProcessor returns [EObject current=null] : iv_ruleProcessor= ruleProcessor EOF ;
    public final EObject entryRuleProcessor() throws RecognitionException {
        EObject current = null;

        EObject iv_ruleProcessor = null;


        try {
            // InternalRsamlText.g:3426:50: (iv_ruleProcessor= ruleProcessor EOF )
            // InternalRsamlText.g:3427:2: iv_ruleProcessor= ruleProcessor EOF
            {
             newCompositeNode(grammarAccess.getProcessorRule()); 
            pushFollow(FOLLOW_1);
            iv_ruleProcessor=ruleProcessor();

            state._fsp--;

             current =iv_ruleProcessor; 
            match(input,EOF,FOLLOW_2); 

            }

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "entryRuleProcessor"


    // $ANTLR start "ruleProcessor"
    // InternalRsamlText.g:3433:1: ruleProcessor returns [EObject current=null] : ( () otherlv_1= 'processor' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'schedPolicy' ( (lv_schedPolicy_6_0= ruleSchedulingPolicy ) ) ) | (otherlv_7= 'core' ( (lv_core_8_0= ruleInteger ) ) ) | (otherlv_9= 'host' ( (lv_host_10_0= RULE_STRING ) ) ) | (otherlv_11= 'linkLatency' ( (lv_linkLatency_12_0= ruleReal ) ) ( (lv_timeUnit_13_0= ruleTimeUnit ) ) ) | this_Unit_14= ruleUnit[$current] | (otherlv_15= 'modules' ( ( ruleQualifiedName ) ) (otherlv_17= ',' ( ( ruleQualifiedName ) ) )* ) )* otherlv_19= '}' ) ;
    public final EObject ruleProcessor() throws RecognitionException {
        EObject current = null;

        Token otherlv_1=null;
        Token otherlv_3=null;
        Token otherlv_5=null;
        Token otherlv_7=null;
        Token otherlv_9=null;
        Token lv_host_10_0=null;
        Token otherlv_11=null;
        Token otherlv_15=null;
        Token otherlv_17=null;
        Token otherlv_19=null;
        AntlrDatatypeRuleToken lv_name_2_0 = null;

        EObject this_Described_4 = null;

        Enumerator lv_schedPolicy_6_0 = null;

        AntlrDatatypeRuleToken lv_core_8_0 = null;

        AntlrDatatypeRuleToken lv_linkLatency_12_0 = null;

        Enumerator lv_timeUnit_13_0 = null;

        EObject this_Unit_14 = null;



        	enterRule();

        try {
            // InternalRsamlText.g:3439:2: ( ( () otherlv_1= 'processor' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'schedPolicy' ( (lv_schedPolicy_6_0= ruleSchedulingPolicy ) ) ) | (otherlv_7= 'core' ( (lv_core_8_0= ruleInteger ) ) ) | (otherlv_9= 'host' ( (lv_host_10_0= RULE_STRING ) ) ) | (otherlv_11= 'linkLatency' ( (lv_linkLatency_12_0= ruleReal ) ) ( (lv_timeUnit_13_0= ruleTimeUnit ) ) ) | this_Unit_14= ruleUnit[$current] | (otherlv_15= 'modules' ( ( ruleQualifiedName ) ) (otherlv_17= ',' ( ( ruleQualifiedName ) ) )* ) )* otherlv_19= '}' ) )
            // InternalRsamlText.g:3440:2: ( () otherlv_1= 'processor' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'schedPolicy' ( (lv_schedPolicy_6_0= ruleSchedulingPolicy ) ) ) | (otherlv_7= 'core' ( (lv_core_8_0= ruleInteger ) ) ) | (otherlv_9= 'host' ( (lv_host_10_0= RULE_STRING ) ) ) | (otherlv_11= 'linkLatency' ( (lv_linkLatency_12_0= ruleReal ) ) ( (lv_timeUnit_13_0= ruleTimeUnit ) ) ) | this_Unit_14= ruleUnit[$current] | (otherlv_15= 'modules' ( ( ruleQualifiedName ) ) (otherlv_17= ',' ( ( ruleQualifiedName ) ) )* ) )* otherlv_19= '}' )
            {
            // InternalRsamlText.g:3440:2: ( () otherlv_1= 'processor' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'schedPolicy' ( (lv_schedPolicy_6_0= ruleSchedulingPolicy ) ) ) | (otherlv_7= 'core' ( (lv_core_8_0= ruleInteger ) ) ) | (otherlv_9= 'host' ( (lv_host_10_0= RULE_STRING ) ) ) | (otherlv_11= 'linkLatency' ( (lv_linkLatency_12_0= ruleReal ) ) ( (lv_timeUnit_13_0= ruleTimeUnit ) ) ) | this_Unit_14= ruleUnit[$current] | (otherlv_15= 'modules' ( ( ruleQualifiedName ) ) (otherlv_17= ',' ( ( ruleQualifiedName ) ) )* ) )* otherlv_19= '}' )
            // InternalRsamlText.g:3441:3: () otherlv_1= 'processor' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'schedPolicy' ( (lv_schedPolicy_6_0= ruleSchedulingPolicy ) ) ) | (otherlv_7= 'core' ( (lv_core_8_0= ruleInteger ) ) ) | (otherlv_9= 'host' ( (lv_host_10_0= RULE_STRING ) ) ) | (otherlv_11= 'linkLatency' ( (lv_linkLatency_12_0= ruleReal ) ) ( (lv_timeUnit_13_0= ruleTimeUnit ) ) ) | this_Unit_14= ruleUnit[$current] | (otherlv_15= 'modules' ( ( ruleQualifiedName ) ) (otherlv_17= ',' ( ( ruleQualifiedName ) ) )* ) )* otherlv_19= '}'
            {
            // InternalRsamlText.g:3441:3: ()
            // InternalRsamlText.g:3442:4: 
            {

            				current = forceCreateModelElement(
            					grammarAccess.getProcessorAccess().getProcessorAction_0(),
            					current);
            			

            }

            otherlv_1=(Token)match(input,71,FOLLOW_3); 

            			newLeafNode(otherlv_1, grammarAccess.getProcessorAccess().getProcessorKeyword_1());
            		
            // InternalRsamlText.g:3452:3: ( (lv_name_2_0= ruleName ) )?
            int alt48=2;
            int LA48_0 = input.LA(1);

            if ( ((LA48_0>=RULE_STRING && LA48_0<=RULE_ID)||LA48_0==11||(LA48_0>=13 && LA48_0<=16)||(LA48_0>=18 && LA48_0<=29)||(LA48_0>=31 && LA48_0<=44)||(LA48_0>=46 && LA48_0<=80)||(LA48_0>=82 && LA48_0<=118)) ) {
                alt48=1;
            }
            switch (alt48) {
                case 1 :
                    // InternalRsamlText.g:3453:4: (lv_name_2_0= ruleName )
                    {
                    // InternalRsamlText.g:3453:4: (lv_name_2_0= ruleName )
                    // InternalRsamlText.g:3454:5: lv_name_2_0= ruleName
                    {

                    					newCompositeNode(grammarAccess.getProcessorAccess().getNameNameParserRuleCall_2_0());
                    				
                    pushFollow(FOLLOW_4);
                    lv_name_2_0=ruleName();

                    state._fsp--;


                    					if (current==null) {
                    						current = createModelElementForParent(grammarAccess.getProcessorRule());
                    					}
                    					set(
                    						current,
                    						"name",
                    						lv_name_2_0,
                    						"org.rsaml.text.RsamlText.Name");
                    					afterParserOrEnumRuleCall();
                    				

                    }


                    }
                    break;

            }

            otherlv_3=(Token)match(input,12,FOLLOW_42); 

            			newLeafNode(otherlv_3, grammarAccess.getProcessorAccess().getLeftCurlyBracketKeyword_3());
            		
            // InternalRsamlText.g:3475:3: (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'schedPolicy' ( (lv_schedPolicy_6_0= ruleSchedulingPolicy ) ) ) | (otherlv_7= 'core' ( (lv_core_8_0= ruleInteger ) ) ) | (otherlv_9= 'host' ( (lv_host_10_0= RULE_STRING ) ) ) | (otherlv_11= 'linkLatency' ( (lv_linkLatency_12_0= ruleReal ) ) ( (lv_timeUnit_13_0= ruleTimeUnit ) ) ) | this_Unit_14= ruleUnit[$current] | (otherlv_15= 'modules' ( ( ruleQualifiedName ) ) (otherlv_17= ',' ( ( ruleQualifiedName ) ) )* ) )*
            loop50:
            do {
                int alt50=8;
                switch ( input.LA(1) ) {
                case 18:
                    {
                    alt50=1;
                    }
                    break;
                case 34:
                    {
                    alt50=2;
                    }
                    break;
                case 72:
                    {
                    alt50=3;
                    }
                    break;
                case 73:
                    {
                    alt50=4;
                    }
                    break;
                case 74:
                    {
                    alt50=5;
                    }
                    break;
                case 19:
                    {
                    alt50=6;
                    }
                    break;
                case 75:
                    {
                    alt50=7;
                    }
                    break;

                }

                switch (alt50) {
            	case 1 :
            	    // InternalRsamlText.g:3476:4: this_Described_4= ruleDescribed[$current]
            	    {

            	    				if (current==null) {
            	    					current = createModelElement(grammarAccess.getProcessorRule());
            	    				}
            	    				newCompositeNode(grammarAccess.getProcessorAccess().getDescribedParserRuleCall_4_0());
            	    			
            	    pushFollow(FOLLOW_42);
            	    this_Described_4=ruleDescribed(current);

            	    state._fsp--;


            	    				current = this_Described_4;
            	    				afterParserOrEnumRuleCall();
            	    			

            	    }
            	    break;
            	case 2 :
            	    // InternalRsamlText.g:3488:4: (otherlv_5= 'schedPolicy' ( (lv_schedPolicy_6_0= ruleSchedulingPolicy ) ) )
            	    {
            	    // InternalRsamlText.g:3488:4: (otherlv_5= 'schedPolicy' ( (lv_schedPolicy_6_0= ruleSchedulingPolicy ) ) )
            	    // InternalRsamlText.g:3489:5: otherlv_5= 'schedPolicy' ( (lv_schedPolicy_6_0= ruleSchedulingPolicy ) )
            	    {
            	    otherlv_5=(Token)match(input,34,FOLLOW_21); 

            	    					newLeafNode(otherlv_5, grammarAccess.getProcessorAccess().getSchedPolicyKeyword_4_1_0());
            	    				
            	    // InternalRsamlText.g:3493:5: ( (lv_schedPolicy_6_0= ruleSchedulingPolicy ) )
            	    // InternalRsamlText.g:3494:6: (lv_schedPolicy_6_0= ruleSchedulingPolicy )
            	    {
            	    // InternalRsamlText.g:3494:6: (lv_schedPolicy_6_0= ruleSchedulingPolicy )
            	    // InternalRsamlText.g:3495:7: lv_schedPolicy_6_0= ruleSchedulingPolicy
            	    {

            	    							newCompositeNode(grammarAccess.getProcessorAccess().getSchedPolicySchedulingPolicyEnumRuleCall_4_1_1_0());
            	    						
            	    pushFollow(FOLLOW_42);
            	    lv_schedPolicy_6_0=ruleSchedulingPolicy();

            	    state._fsp--;


            	    							if (current==null) {
            	    								current = createModelElementForParent(grammarAccess.getProcessorRule());
            	    							}
            	    							set(
            	    								current,
            	    								"schedPolicy",
            	    								lv_schedPolicy_6_0,
            	    								"org.rsaml.text.RsamlText.SchedulingPolicy");
            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;
            	case 3 :
            	    // InternalRsamlText.g:3514:4: (otherlv_7= 'core' ( (lv_core_8_0= ruleInteger ) ) )
            	    {
            	    // InternalRsamlText.g:3514:4: (otherlv_7= 'core' ( (lv_core_8_0= ruleInteger ) ) )
            	    // InternalRsamlText.g:3515:5: otherlv_7= 'core' ( (lv_core_8_0= ruleInteger ) )
            	    {
            	    otherlv_7=(Token)match(input,72,FOLLOW_7); 

            	    					newLeafNode(otherlv_7, grammarAccess.getProcessorAccess().getCoreKeyword_4_2_0());
            	    				
            	    // InternalRsamlText.g:3519:5: ( (lv_core_8_0= ruleInteger ) )
            	    // InternalRsamlText.g:3520:6: (lv_core_8_0= ruleInteger )
            	    {
            	    // InternalRsamlText.g:3520:6: (lv_core_8_0= ruleInteger )
            	    // InternalRsamlText.g:3521:7: lv_core_8_0= ruleInteger
            	    {

            	    							newCompositeNode(grammarAccess.getProcessorAccess().getCoreIntegerParserRuleCall_4_2_1_0());
            	    						
            	    pushFollow(FOLLOW_42);
            	    lv_core_8_0=ruleInteger();

            	    state._fsp--;


            	    							if (current==null) {
            	    								current = createModelElementForParent(grammarAccess.getProcessorRule());
            	    							}
            	    							set(
            	    								current,
            	    								"core",
            	    								lv_core_8_0,
            	    								"org.rsaml.text.RsamlText.Integer");
            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;
            	case 4 :
            	    // InternalRsamlText.g:3540:4: (otherlv_9= 'host' ( (lv_host_10_0= RULE_STRING ) ) )
            	    {
            	    // InternalRsamlText.g:3540:4: (otherlv_9= 'host' ( (lv_host_10_0= RULE_STRING ) ) )
            	    // InternalRsamlText.g:3541:5: otherlv_9= 'host' ( (lv_host_10_0= RULE_STRING ) )
            	    {
            	    otherlv_9=(Token)match(input,73,FOLLOW_10); 

            	    					newLeafNode(otherlv_9, grammarAccess.getProcessorAccess().getHostKeyword_4_3_0());
            	    				
            	    // InternalRsamlText.g:3545:5: ( (lv_host_10_0= RULE_STRING ) )
            	    // InternalRsamlText.g:3546:6: (lv_host_10_0= RULE_STRING )
            	    {
            	    // InternalRsamlText.g:3546:6: (lv_host_10_0= RULE_STRING )
            	    // InternalRsamlText.g:3547:7: lv_host_10_0= RULE_STRING
            	    {
            	    lv_host_10_0=(Token)match(input,RULE_STRING,FOLLOW_42); 

            	    							newLeafNode(lv_host_10_0, grammarAccess.getProcessorAccess().getHostSTRINGTerminalRuleCall_4_3_1_0());
            	    						

            	    							if (current==null) {
            	    								current = createModelElement(grammarAccess.getProcessorRule());
            	    							}
            	    							setWithLastConsumed(
            	    								current,
            	    								"host",
            	    								lv_host_10_0,
            	    								"org.rsaml.text.RsamlText.STRING");
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;
            	case 5 :
            	    // InternalRsamlText.g:3565:4: (otherlv_11= 'linkLatency' ( (lv_linkLatency_12_0= ruleReal ) ) ( (lv_timeUnit_13_0= ruleTimeUnit ) ) )
            	    {
            	    // InternalRsamlText.g:3565:4: (otherlv_11= 'linkLatency' ( (lv_linkLatency_12_0= ruleReal ) ) ( (lv_timeUnit_13_0= ruleTimeUnit ) ) )
            	    // InternalRsamlText.g:3566:5: otherlv_11= 'linkLatency' ( (lv_linkLatency_12_0= ruleReal ) ) ( (lv_timeUnit_13_0= ruleTimeUnit ) )
            	    {
            	    otherlv_11=(Token)match(input,74,FOLLOW_14); 

            	    					newLeafNode(otherlv_11, grammarAccess.getProcessorAccess().getLinkLatencyKeyword_4_4_0());
            	    				
            	    // InternalRsamlText.g:3570:5: ( (lv_linkLatency_12_0= ruleReal ) )
            	    // InternalRsamlText.g:3571:6: (lv_linkLatency_12_0= ruleReal )
            	    {
            	    // InternalRsamlText.g:3571:6: (lv_linkLatency_12_0= ruleReal )
            	    // InternalRsamlText.g:3572:7: lv_linkLatency_12_0= ruleReal
            	    {

            	    							newCompositeNode(grammarAccess.getProcessorAccess().getLinkLatencyRealParserRuleCall_4_4_1_0());
            	    						
            	    pushFollow(FOLLOW_11);
            	    lv_linkLatency_12_0=ruleReal();

            	    state._fsp--;


            	    							if (current==null) {
            	    								current = createModelElementForParent(grammarAccess.getProcessorRule());
            	    							}
            	    							set(
            	    								current,
            	    								"linkLatency",
            	    								lv_linkLatency_12_0,
            	    								"org.rsaml.text.RsamlText.Real");
            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }

            	    // InternalRsamlText.g:3589:5: ( (lv_timeUnit_13_0= ruleTimeUnit ) )
            	    // InternalRsamlText.g:3590:6: (lv_timeUnit_13_0= ruleTimeUnit )
            	    {
            	    // InternalRsamlText.g:3590:6: (lv_timeUnit_13_0= ruleTimeUnit )
            	    // InternalRsamlText.g:3591:7: lv_timeUnit_13_0= ruleTimeUnit
            	    {

            	    							newCompositeNode(grammarAccess.getProcessorAccess().getTimeUnitTimeUnitEnumRuleCall_4_4_2_0());
            	    						
            	    pushFollow(FOLLOW_42);
            	    lv_timeUnit_13_0=ruleTimeUnit();

            	    state._fsp--;


            	    							if (current==null) {
            	    								current = createModelElementForParent(grammarAccess.getProcessorRule());
            	    							}
            	    							set(
            	    								current,
            	    								"timeUnit",
            	    								lv_timeUnit_13_0,
            	    								"org.rsaml.text.RsamlText.TimeUnit");
            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;
            	case 6 :
            	    // InternalRsamlText.g:3610:4: this_Unit_14= ruleUnit[$current]
            	    {

            	    				if (current==null) {
            	    					current = createModelElement(grammarAccess.getProcessorRule());
            	    				}
            	    				newCompositeNode(grammarAccess.getProcessorAccess().getUnitParserRuleCall_4_5());
            	    			
            	    pushFollow(FOLLOW_42);
            	    this_Unit_14=ruleUnit(current);

            	    state._fsp--;


            	    				current = this_Unit_14;
            	    				afterParserOrEnumRuleCall();
            	    			

            	    }
            	    break;
            	case 7 :
            	    // InternalRsamlText.g:3622:4: (otherlv_15= 'modules' ( ( ruleQualifiedName ) ) (otherlv_17= ',' ( ( ruleQualifiedName ) ) )* )
            	    {
            	    // InternalRsamlText.g:3622:4: (otherlv_15= 'modules' ( ( ruleQualifiedName ) ) (otherlv_17= ',' ( ( ruleQualifiedName ) ) )* )
            	    // InternalRsamlText.g:3623:5: otherlv_15= 'modules' ( ( ruleQualifiedName ) ) (otherlv_17= ',' ( ( ruleQualifiedName ) ) )*
            	    {
            	    otherlv_15=(Token)match(input,75,FOLLOW_17); 

            	    					newLeafNode(otherlv_15, grammarAccess.getProcessorAccess().getModulesKeyword_4_6_0());
            	    				
            	    // InternalRsamlText.g:3627:5: ( ( ruleQualifiedName ) )
            	    // InternalRsamlText.g:3628:6: ( ruleQualifiedName )
            	    {
            	    // InternalRsamlText.g:3628:6: ( ruleQualifiedName )
            	    // InternalRsamlText.g:3629:7: ruleQualifiedName
            	    {

            	    							if (current==null) {
            	    								current = createModelElement(grammarAccess.getProcessorRule());
            	    							}
            	    						

            	    							newCompositeNode(grammarAccess.getProcessorAccess().getModulesModuleCrossReference_4_6_1_0());
            	    						
            	    pushFollow(FOLLOW_43);
            	    ruleQualifiedName();

            	    state._fsp--;


            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }

            	    // InternalRsamlText.g:3643:5: (otherlv_17= ',' ( ( ruleQualifiedName ) ) )*
            	    loop49:
            	    do {
            	        int alt49=2;
            	        int LA49_0 = input.LA(1);

            	        if ( (LA49_0==30) ) {
            	            alt49=1;
            	        }


            	        switch (alt49) {
            	    	case 1 :
            	    	    // InternalRsamlText.g:3644:6: otherlv_17= ',' ( ( ruleQualifiedName ) )
            	    	    {
            	    	    otherlv_17=(Token)match(input,30,FOLLOW_17); 

            	    	    						newLeafNode(otherlv_17, grammarAccess.getProcessorAccess().getCommaKeyword_4_6_2_0());
            	    	    					
            	    	    // InternalRsamlText.g:3648:6: ( ( ruleQualifiedName ) )
            	    	    // InternalRsamlText.g:3649:7: ( ruleQualifiedName )
            	    	    {
            	    	    // InternalRsamlText.g:3649:7: ( ruleQualifiedName )
            	    	    // InternalRsamlText.g:3650:8: ruleQualifiedName
            	    	    {

            	    	    								if (current==null) {
            	    	    									current = createModelElement(grammarAccess.getProcessorRule());
            	    	    								}
            	    	    							

            	    	    								newCompositeNode(grammarAccess.getProcessorAccess().getModulesModuleCrossReference_4_6_2_1_0());
            	    	    							
            	    	    pushFollow(FOLLOW_43);
            	    	    ruleQualifiedName();

            	    	    state._fsp--;


            	    	    								afterParserOrEnumRuleCall();
            	    	    							

            	    	    }


            	    	    }


            	    	    }
            	    	    break;

            	    	default :
            	    	    break loop49;
            	        }
            	    } while (true);


            	    }


            	    }
            	    break;

            	default :
            	    break loop50;
                }
            } while (true);

            otherlv_19=(Token)match(input,17,FOLLOW_2); 

            			newLeafNode(otherlv_19, grammarAccess.getProcessorAccess().getRightCurlyBracketKeyword_5());
            		

            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "ruleProcessor"


    // $ANTLR start "entryRuleLatencyRequirement"
    // InternalRsamlText.g:3675:1: entryRuleLatencyRequirement returns [EObject current=null] : iv_ruleLatencyRequirement= ruleLatencyRequirement EOF ;
    public final EObject entryRuleLatencyRequirement() throws RecognitionException {
        EObject current = null;

        EObject iv_ruleLatencyRequirement = null;


        try {
            // InternalRsamlText.g:3675:59: (iv_ruleLatencyRequirement= ruleLatencyRequirement EOF )
            // InternalRsamlText.g:3676:2: iv_ruleLatencyRequirement= ruleLatencyRequirement EOF
            {
             newCompositeNode(grammarAccess.getLatencyRequirementRule()); 
            pushFollow(FOLLOW_1);
            iv_ruleLatencyRequirement=ruleLatencyRequirement();

            state._fsp--;

             current =iv_ruleLatencyRequirement; 
            match(input,EOF,FOLLOW_2); 

            }

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "entryRuleLatencyRequirement"


    // $ANTLR start "ruleLatencyRequirement"
    // InternalRsamlText.g:3682:1: ruleLatencyRequirement returns [EObject current=null] : ( () otherlv_1= 'latency' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'from' ( ( ruleQualifiedName ) ) ) | (otherlv_7= 'to' ( ( ruleQualifiedName ) ) ) | (otherlv_9= 'via' ( ( ruleQualifiedName ) ) (otherlv_11= ',' ( ( ruleQualifiedName ) ) )* ) | (otherlv_13= 'maxLatency' ( (lv_maxLatency_14_0= ruleReal ) ) ( (lv_timeUnit_15_0= ruleTimeUnit ) ) ) | (otherlv_16= 'kind' ( (lv_kind_17_0= ruleLatencyKind ) ) ) | this_Unit_18= ruleUnit[$current] )* otherlv_19= '}' ) ;
    public final EObject ruleLatencyRequirement() throws RecognitionException {
        EObject current = null;

        Token otherlv_1=null;
        Token otherlv_3=null;
        Token otherlv_5=null;
        Token otherlv_7=null;
        Token otherlv_9=null;
        Token otherlv_11=null;
        Token otherlv_13=null;
        Token otherlv_16=null;
        Token otherlv_19=null;
        AntlrDatatypeRuleToken lv_name_2_0 = null;

        EObject this_Described_4 = null;

        AntlrDatatypeRuleToken lv_maxLatency_14_0 = null;

        Enumerator lv_timeUnit_15_0 = null;

        Enumerator lv_kind_17_0 = null;

        EObject this_Unit_18 = null;



        	enterRule();

        try {
            // InternalRsamlText.g:3688:2: ( ( () otherlv_1= 'latency' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'from' ( ( ruleQualifiedName ) ) ) | (otherlv_7= 'to' ( ( ruleQualifiedName ) ) ) | (otherlv_9= 'via' ( ( ruleQualifiedName ) ) (otherlv_11= ',' ( ( ruleQualifiedName ) ) )* ) | (otherlv_13= 'maxLatency' ( (lv_maxLatency_14_0= ruleReal ) ) ( (lv_timeUnit_15_0= ruleTimeUnit ) ) ) | (otherlv_16= 'kind' ( (lv_kind_17_0= ruleLatencyKind ) ) ) | this_Unit_18= ruleUnit[$current] )* otherlv_19= '}' ) )
            // InternalRsamlText.g:3689:2: ( () otherlv_1= 'latency' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'from' ( ( ruleQualifiedName ) ) ) | (otherlv_7= 'to' ( ( ruleQualifiedName ) ) ) | (otherlv_9= 'via' ( ( ruleQualifiedName ) ) (otherlv_11= ',' ( ( ruleQualifiedName ) ) )* ) | (otherlv_13= 'maxLatency' ( (lv_maxLatency_14_0= ruleReal ) ) ( (lv_timeUnit_15_0= ruleTimeUnit ) ) ) | (otherlv_16= 'kind' ( (lv_kind_17_0= ruleLatencyKind ) ) ) | this_Unit_18= ruleUnit[$current] )* otherlv_19= '}' )
            {
            // InternalRsamlText.g:3689:2: ( () otherlv_1= 'latency' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'from' ( ( ruleQualifiedName ) ) ) | (otherlv_7= 'to' ( ( ruleQualifiedName ) ) ) | (otherlv_9= 'via' ( ( ruleQualifiedName ) ) (otherlv_11= ',' ( ( ruleQualifiedName ) ) )* ) | (otherlv_13= 'maxLatency' ( (lv_maxLatency_14_0= ruleReal ) ) ( (lv_timeUnit_15_0= ruleTimeUnit ) ) ) | (otherlv_16= 'kind' ( (lv_kind_17_0= ruleLatencyKind ) ) ) | this_Unit_18= ruleUnit[$current] )* otherlv_19= '}' )
            // InternalRsamlText.g:3690:3: () otherlv_1= 'latency' ( (lv_name_2_0= ruleName ) )? otherlv_3= '{' (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'from' ( ( ruleQualifiedName ) ) ) | (otherlv_7= 'to' ( ( ruleQualifiedName ) ) ) | (otherlv_9= 'via' ( ( ruleQualifiedName ) ) (otherlv_11= ',' ( ( ruleQualifiedName ) ) )* ) | (otherlv_13= 'maxLatency' ( (lv_maxLatency_14_0= ruleReal ) ) ( (lv_timeUnit_15_0= ruleTimeUnit ) ) ) | (otherlv_16= 'kind' ( (lv_kind_17_0= ruleLatencyKind ) ) ) | this_Unit_18= ruleUnit[$current] )* otherlv_19= '}'
            {
            // InternalRsamlText.g:3690:3: ()
            // InternalRsamlText.g:3691:4: 
            {

            				current = forceCreateModelElement(
            					grammarAccess.getLatencyRequirementAccess().getLatencyRequirementAction_0(),
            					current);
            			

            }

            otherlv_1=(Token)match(input,76,FOLLOW_3); 

            			newLeafNode(otherlv_1, grammarAccess.getLatencyRequirementAccess().getLatencyKeyword_1());
            		
            // InternalRsamlText.g:3701:3: ( (lv_name_2_0= ruleName ) )?
            int alt51=2;
            int LA51_0 = input.LA(1);

            if ( ((LA51_0>=RULE_STRING && LA51_0<=RULE_ID)||LA51_0==11||(LA51_0>=13 && LA51_0<=16)||(LA51_0>=18 && LA51_0<=29)||(LA51_0>=31 && LA51_0<=44)||(LA51_0>=46 && LA51_0<=80)||(LA51_0>=82 && LA51_0<=118)) ) {
                alt51=1;
            }
            switch (alt51) {
                case 1 :
                    // InternalRsamlText.g:3702:4: (lv_name_2_0= ruleName )
                    {
                    // InternalRsamlText.g:3702:4: (lv_name_2_0= ruleName )
                    // InternalRsamlText.g:3703:5: lv_name_2_0= ruleName
                    {

                    					newCompositeNode(grammarAccess.getLatencyRequirementAccess().getNameNameParserRuleCall_2_0());
                    				
                    pushFollow(FOLLOW_4);
                    lv_name_2_0=ruleName();

                    state._fsp--;


                    					if (current==null) {
                    						current = createModelElementForParent(grammarAccess.getLatencyRequirementRule());
                    					}
                    					set(
                    						current,
                    						"name",
                    						lv_name_2_0,
                    						"org.rsaml.text.RsamlText.Name");
                    					afterParserOrEnumRuleCall();
                    				

                    }


                    }
                    break;

            }

            otherlv_3=(Token)match(input,12,FOLLOW_44); 

            			newLeafNode(otherlv_3, grammarAccess.getLatencyRequirementAccess().getLeftCurlyBracketKeyword_3());
            		
            // InternalRsamlText.g:3724:3: (this_Described_4= ruleDescribed[$current] | (otherlv_5= 'from' ( ( ruleQualifiedName ) ) ) | (otherlv_7= 'to' ( ( ruleQualifiedName ) ) ) | (otherlv_9= 'via' ( ( ruleQualifiedName ) ) (otherlv_11= ',' ( ( ruleQualifiedName ) ) )* ) | (otherlv_13= 'maxLatency' ( (lv_maxLatency_14_0= ruleReal ) ) ( (lv_timeUnit_15_0= ruleTimeUnit ) ) ) | (otherlv_16= 'kind' ( (lv_kind_17_0= ruleLatencyKind ) ) ) | this_Unit_18= ruleUnit[$current] )*
            loop53:
            do {
                int alt53=8;
                switch ( input.LA(1) ) {
                case 18:
                    {
                    alt53=1;
                    }
                    break;
                case 77:
                    {
                    alt53=2;
                    }
                    break;
                case 78:
                    {
                    alt53=3;
                    }
                    break;
                case 79:
                    {
                    alt53=4;
                    }
                    break;
                case 80:
                    {
                    alt53=5;
                    }
                    break;
                case 52:
                    {
                    alt53=6;
                    }
                    break;
                case 19:
                    {
                    alt53=7;
                    }
                    break;

                }

                switch (alt53) {
            	case 1 :
            	    // InternalRsamlText.g:3725:4: this_Described_4= ruleDescribed[$current]
            	    {

            	    				if (current==null) {
            	    					current = createModelElement(grammarAccess.getLatencyRequirementRule());
            	    				}
            	    				newCompositeNode(grammarAccess.getLatencyRequirementAccess().getDescribedParserRuleCall_4_0());
            	    			
            	    pushFollow(FOLLOW_44);
            	    this_Described_4=ruleDescribed(current);

            	    state._fsp--;


            	    				current = this_Described_4;
            	    				afterParserOrEnumRuleCall();
            	    			

            	    }
            	    break;
            	case 2 :
            	    // InternalRsamlText.g:3737:4: (otherlv_5= 'from' ( ( ruleQualifiedName ) ) )
            	    {
            	    // InternalRsamlText.g:3737:4: (otherlv_5= 'from' ( ( ruleQualifiedName ) ) )
            	    // InternalRsamlText.g:3738:5: otherlv_5= 'from' ( ( ruleQualifiedName ) )
            	    {
            	    otherlv_5=(Token)match(input,77,FOLLOW_17); 

            	    					newLeafNode(otherlv_5, grammarAccess.getLatencyRequirementAccess().getFromKeyword_4_1_0());
            	    				
            	    // InternalRsamlText.g:3742:5: ( ( ruleQualifiedName ) )
            	    // InternalRsamlText.g:3743:6: ( ruleQualifiedName )
            	    {
            	    // InternalRsamlText.g:3743:6: ( ruleQualifiedName )
            	    // InternalRsamlText.g:3744:7: ruleQualifiedName
            	    {

            	    							if (current==null) {
            	    								current = createModelElement(grammarAccess.getLatencyRequirementRule());
            	    							}
            	    						

            	    							newCompositeNode(grammarAccess.getLatencyRequirementAccess().getSourceNamedElementCrossReference_4_1_1_0());
            	    						
            	    pushFollow(FOLLOW_44);
            	    ruleQualifiedName();

            	    state._fsp--;


            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;
            	case 3 :
            	    // InternalRsamlText.g:3760:4: (otherlv_7= 'to' ( ( ruleQualifiedName ) ) )
            	    {
            	    // InternalRsamlText.g:3760:4: (otherlv_7= 'to' ( ( ruleQualifiedName ) ) )
            	    // InternalRsamlText.g:3761:5: otherlv_7= 'to' ( ( ruleQualifiedName ) )
            	    {
            	    otherlv_7=(Token)match(input,78,FOLLOW_17); 

            	    					newLeafNode(otherlv_7, grammarAccess.getLatencyRequirementAccess().getToKeyword_4_2_0());
            	    				
            	    // InternalRsamlText.g:3765:5: ( ( ruleQualifiedName ) )
            	    // InternalRsamlText.g:3766:6: ( ruleQualifiedName )
            	    {
            	    // InternalRsamlText.g:3766:6: ( ruleQualifiedName )
            	    // InternalRsamlText.g:3767:7: ruleQualifiedName
            	    {

            	    							if (current==null) {
            	    								current = createModelElement(grammarAccess.getLatencyRequirementRule());
            	    							}
            	    						

            	    							newCompositeNode(grammarAccess.getLatencyRequirementAccess().getTargetNamedElementCrossReference_4_2_1_0());
            	    						
            	    pushFollow(FOLLOW_44);
            	    ruleQualifiedName();

            	    state._fsp--;


            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;
            	case 4 :
            	    // InternalRsamlText.g:3783:4: (otherlv_9= 'via' ( ( ruleQualifiedName ) ) (otherlv_11= ',' ( ( ruleQualifiedName ) ) )* )
            	    {
            	    // InternalRsamlText.g:3783:4: (otherlv_9= 'via' ( ( ruleQualifiedName ) ) (otherlv_11= ',' ( ( ruleQualifiedName ) ) )* )
            	    // InternalRsamlText.g:3784:5: otherlv_9= 'via' ( ( ruleQualifiedName ) ) (otherlv_11= ',' ( ( ruleQualifiedName ) ) )*
            	    {
            	    otherlv_9=(Token)match(input,79,FOLLOW_17); 

            	    					newLeafNode(otherlv_9, grammarAccess.getLatencyRequirementAccess().getViaKeyword_4_3_0());
            	    				
            	    // InternalRsamlText.g:3788:5: ( ( ruleQualifiedName ) )
            	    // InternalRsamlText.g:3789:6: ( ruleQualifiedName )
            	    {
            	    // InternalRsamlText.g:3789:6: ( ruleQualifiedName )
            	    // InternalRsamlText.g:3790:7: ruleQualifiedName
            	    {

            	    							if (current==null) {
            	    								current = createModelElement(grammarAccess.getLatencyRequirementRule());
            	    							}
            	    						

            	    							newCompositeNode(grammarAccess.getLatencyRequirementAccess().getViaNamedElementCrossReference_4_3_1_0());
            	    						
            	    pushFollow(FOLLOW_45);
            	    ruleQualifiedName();

            	    state._fsp--;


            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }

            	    // InternalRsamlText.g:3804:5: (otherlv_11= ',' ( ( ruleQualifiedName ) ) )*
            	    loop52:
            	    do {
            	        int alt52=2;
            	        int LA52_0 = input.LA(1);

            	        if ( (LA52_0==30) ) {
            	            alt52=1;
            	        }


            	        switch (alt52) {
            	    	case 1 :
            	    	    // InternalRsamlText.g:3805:6: otherlv_11= ',' ( ( ruleQualifiedName ) )
            	    	    {
            	    	    otherlv_11=(Token)match(input,30,FOLLOW_17); 

            	    	    						newLeafNode(otherlv_11, grammarAccess.getLatencyRequirementAccess().getCommaKeyword_4_3_2_0());
            	    	    					
            	    	    // InternalRsamlText.g:3809:6: ( ( ruleQualifiedName ) )
            	    	    // InternalRsamlText.g:3810:7: ( ruleQualifiedName )
            	    	    {
            	    	    // InternalRsamlText.g:3810:7: ( ruleQualifiedName )
            	    	    // InternalRsamlText.g:3811:8: ruleQualifiedName
            	    	    {

            	    	    								if (current==null) {
            	    	    									current = createModelElement(grammarAccess.getLatencyRequirementRule());
            	    	    								}
            	    	    							

            	    	    								newCompositeNode(grammarAccess.getLatencyRequirementAccess().getViaNamedElementCrossReference_4_3_2_1_0());
            	    	    							
            	    	    pushFollow(FOLLOW_45);
            	    	    ruleQualifiedName();

            	    	    state._fsp--;


            	    	    								afterParserOrEnumRuleCall();
            	    	    							

            	    	    }


            	    	    }


            	    	    }
            	    	    break;

            	    	default :
            	    	    break loop52;
            	        }
            	    } while (true);


            	    }


            	    }
            	    break;
            	case 5 :
            	    // InternalRsamlText.g:3828:4: (otherlv_13= 'maxLatency' ( (lv_maxLatency_14_0= ruleReal ) ) ( (lv_timeUnit_15_0= ruleTimeUnit ) ) )
            	    {
            	    // InternalRsamlText.g:3828:4: (otherlv_13= 'maxLatency' ( (lv_maxLatency_14_0= ruleReal ) ) ( (lv_timeUnit_15_0= ruleTimeUnit ) ) )
            	    // InternalRsamlText.g:3829:5: otherlv_13= 'maxLatency' ( (lv_maxLatency_14_0= ruleReal ) ) ( (lv_timeUnit_15_0= ruleTimeUnit ) )
            	    {
            	    otherlv_13=(Token)match(input,80,FOLLOW_14); 

            	    					newLeafNode(otherlv_13, grammarAccess.getLatencyRequirementAccess().getMaxLatencyKeyword_4_4_0());
            	    				
            	    // InternalRsamlText.g:3833:5: ( (lv_maxLatency_14_0= ruleReal ) )
            	    // InternalRsamlText.g:3834:6: (lv_maxLatency_14_0= ruleReal )
            	    {
            	    // InternalRsamlText.g:3834:6: (lv_maxLatency_14_0= ruleReal )
            	    // InternalRsamlText.g:3835:7: lv_maxLatency_14_0= ruleReal
            	    {

            	    							newCompositeNode(grammarAccess.getLatencyRequirementAccess().getMaxLatencyRealParserRuleCall_4_4_1_0());
            	    						
            	    pushFollow(FOLLOW_11);
            	    lv_maxLatency_14_0=ruleReal();

            	    state._fsp--;


            	    							if (current==null) {
            	    								current = createModelElementForParent(grammarAccess.getLatencyRequirementRule());
            	    							}
            	    							set(
            	    								current,
            	    								"maxLatency",
            	    								lv_maxLatency_14_0,
            	    								"org.rsaml.text.RsamlText.Real");
            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }

            	    // InternalRsamlText.g:3852:5: ( (lv_timeUnit_15_0= ruleTimeUnit ) )
            	    // InternalRsamlText.g:3853:6: (lv_timeUnit_15_0= ruleTimeUnit )
            	    {
            	    // InternalRsamlText.g:3853:6: (lv_timeUnit_15_0= ruleTimeUnit )
            	    // InternalRsamlText.g:3854:7: lv_timeUnit_15_0= ruleTimeUnit
            	    {

            	    							newCompositeNode(grammarAccess.getLatencyRequirementAccess().getTimeUnitTimeUnitEnumRuleCall_4_4_2_0());
            	    						
            	    pushFollow(FOLLOW_44);
            	    lv_timeUnit_15_0=ruleTimeUnit();

            	    state._fsp--;


            	    							if (current==null) {
            	    								current = createModelElementForParent(grammarAccess.getLatencyRequirementRule());
            	    							}
            	    							set(
            	    								current,
            	    								"timeUnit",
            	    								lv_timeUnit_15_0,
            	    								"org.rsaml.text.RsamlText.TimeUnit");
            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;
            	case 6 :
            	    // InternalRsamlText.g:3873:4: (otherlv_16= 'kind' ( (lv_kind_17_0= ruleLatencyKind ) ) )
            	    {
            	    // InternalRsamlText.g:3873:4: (otherlv_16= 'kind' ( (lv_kind_17_0= ruleLatencyKind ) ) )
            	    // InternalRsamlText.g:3874:5: otherlv_16= 'kind' ( (lv_kind_17_0= ruleLatencyKind ) )
            	    {
            	    otherlv_16=(Token)match(input,52,FOLLOW_46); 

            	    					newLeafNode(otherlv_16, grammarAccess.getLatencyRequirementAccess().getKindKeyword_4_5_0());
            	    				
            	    // InternalRsamlText.g:3878:5: ( (lv_kind_17_0= ruleLatencyKind ) )
            	    // InternalRsamlText.g:3879:6: (lv_kind_17_0= ruleLatencyKind )
            	    {
            	    // InternalRsamlText.g:3879:6: (lv_kind_17_0= ruleLatencyKind )
            	    // InternalRsamlText.g:3880:7: lv_kind_17_0= ruleLatencyKind
            	    {

            	    							newCompositeNode(grammarAccess.getLatencyRequirementAccess().getKindLatencyKindEnumRuleCall_4_5_1_0());
            	    						
            	    pushFollow(FOLLOW_44);
            	    lv_kind_17_0=ruleLatencyKind();

            	    state._fsp--;


            	    							if (current==null) {
            	    								current = createModelElementForParent(grammarAccess.getLatencyRequirementRule());
            	    							}
            	    							set(
            	    								current,
            	    								"kind",
            	    								lv_kind_17_0,
            	    								"org.rsaml.text.RsamlText.LatencyKind");
            	    							afterParserOrEnumRuleCall();
            	    						

            	    }


            	    }


            	    }


            	    }
            	    break;
            	case 7 :
            	    // InternalRsamlText.g:3899:4: this_Unit_18= ruleUnit[$current]
            	    {

            	    				if (current==null) {
            	    					current = createModelElement(grammarAccess.getLatencyRequirementRule());
            	    				}
            	    				newCompositeNode(grammarAccess.getLatencyRequirementAccess().getUnitParserRuleCall_4_6());
            	    			
            	    pushFollow(FOLLOW_44);
            	    this_Unit_18=ruleUnit(current);

            	    state._fsp--;


            	    				current = this_Unit_18;
            	    				afterParserOrEnumRuleCall();
            	    			

            	    }
            	    break;

            	default :
            	    break loop53;
                }
            } while (true);

            otherlv_19=(Token)match(input,17,FOLLOW_2); 

            			newLeafNode(otherlv_19, grammarAccess.getLatencyRequirementAccess().getRightCurlyBracketKeyword_5());
            		

            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "ruleLatencyRequirement"


    // $ANTLR start "entryRuleName"
    // InternalRsamlText.g:3919:1: entryRuleName returns [String current=null] : iv_ruleName= ruleName EOF ;
    public final String entryRuleName() throws RecognitionException {
        String current = null;

        AntlrDatatypeRuleToken iv_ruleName = null;


        try {
            // InternalRsamlText.g:3919:44: (iv_ruleName= ruleName EOF )
            // InternalRsamlText.g:3920:2: iv_ruleName= ruleName EOF
            {
             newCompositeNode(grammarAccess.getNameRule()); 
            pushFollow(FOLLOW_1);
            iv_ruleName=ruleName();

            state._fsp--;

             current =iv_ruleName.getText(); 
            match(input,EOF,FOLLOW_2); 

            }

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "entryRuleName"


    // $ANTLR start "ruleName"
    // InternalRsamlText.g:3926:1: ruleName returns [AntlrDatatypeRuleToken current=new AntlrDatatypeRuleToken()] : (this_ID_0= RULE_ID | this_STRING_1= RULE_STRING | this_Keyword_2= ruleKeyword ) ;
    public final AntlrDatatypeRuleToken ruleName() throws RecognitionException {
        AntlrDatatypeRuleToken current = new AntlrDatatypeRuleToken();

        Token this_ID_0=null;
        Token this_STRING_1=null;
        AntlrDatatypeRuleToken this_Keyword_2 = null;



        	enterRule();

        try {
            // InternalRsamlText.g:3932:2: ( (this_ID_0= RULE_ID | this_STRING_1= RULE_STRING | this_Keyword_2= ruleKeyword ) )
            // InternalRsamlText.g:3933:2: (this_ID_0= RULE_ID | this_STRING_1= RULE_STRING | this_Keyword_2= ruleKeyword )
            {
            // InternalRsamlText.g:3933:2: (this_ID_0= RULE_ID | this_STRING_1= RULE_STRING | this_Keyword_2= ruleKeyword )
            int alt54=3;
            switch ( input.LA(1) ) {
            case RULE_ID:
                {
                alt54=1;
                }
                break;
            case RULE_STRING:
                {
                alt54=2;
                }
                break;
            case 11:
            case 13:
            case 14:
            case 15:
            case 16:
            case 18:
            case 19:
            case 20:
            case 21:
            case 22:
            case 23:
            case 24:
            case 25:
            case 26:
            case 27:
            case 28:
            case 29:
            case 31:
            case 32:
            case 33:
            case 34:
            case 35:
            case 36:
            case 37:
            case 38:
            case 39:
            case 40:
            case 41:
            case 42:
            case 43:
            case 44:
            case 46:
            case 47:
            case 48:
            case 49:
            case 50:
            case 51:
            case 52:
            case 53:
            case 54:
            case 55:
            case 56:
            case 57:
            case 58:
            case 59:
            case 60:
            case 61:
            case 62:
            case 63:
            case 64:
            case 65:
            case 66:
            case 67:
            case 68:
            case 69:
            case 70:
            case 71:
            case 72:
            case 73:
            case 74:
            case 75:
            case 76:
            case 77:
            case 78:
            case 79:
            case 80:
            case 82:
            case 83:
            case 84:
            case 85:
            case 86:
            case 87:
            case 88:
            case 89:
            case 90:
            case 91:
            case 92:
            case 93:
            case 94:
            case 95:
            case 96:
            case 97:
            case 98:
            case 99:
            case 100:
            case 101:
            case 102:
            case 103:
            case 104:
            case 105:
            case 106:
            case 107:
            case 108:
            case 109:
            case 110:
            case 111:
            case 112:
            case 113:
            case 114:
            case 115:
            case 116:
            case 117:
            case 118:
                {
                alt54=3;
                }
                break;
            default:
                NoViableAltException nvae =
                    new NoViableAltException("", 54, 0, input);

                throw nvae;
            }

            switch (alt54) {
                case 1 :
                    // InternalRsamlText.g:3934:3: this_ID_0= RULE_ID
                    {
                    this_ID_0=(Token)match(input,RULE_ID,FOLLOW_2); 

                    			current.merge(this_ID_0);
                    		

                    			newLeafNode(this_ID_0, grammarAccess.getNameAccess().getIDTerminalRuleCall_0());
                    		

                    }
                    break;
                case 2 :
                    // InternalRsamlText.g:3942:3: this_STRING_1= RULE_STRING
                    {
                    this_STRING_1=(Token)match(input,RULE_STRING,FOLLOW_2); 

                    			current.merge(this_STRING_1);
                    		

                    			newLeafNode(this_STRING_1, grammarAccess.getNameAccess().getSTRINGTerminalRuleCall_1());
                    		

                    }
                    break;
                case 3 :
                    // InternalRsamlText.g:3950:3: this_Keyword_2= ruleKeyword
                    {

                    			newCompositeNode(grammarAccess.getNameAccess().getKeywordParserRuleCall_2());
                    		
                    pushFollow(FOLLOW_2);
                    this_Keyword_2=ruleKeyword();

                    state._fsp--;


                    			current.merge(this_Keyword_2);
                    		

                    			afterParserOrEnumRuleCall();
                    		

                    }
                    break;

            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "ruleName"


    // $ANTLR start "entryRuleQualifiedName"
    // InternalRsamlText.g:3964:1: entryRuleQualifiedName returns [String current=null] : iv_ruleQualifiedName= ruleQualifiedName EOF ;
    public final String entryRuleQualifiedName() throws RecognitionException {
        String current = null;

        AntlrDatatypeRuleToken iv_ruleQualifiedName = null;


        try {
            // InternalRsamlText.g:3964:53: (iv_ruleQualifiedName= ruleQualifiedName EOF )
            // InternalRsamlText.g:3965:2: iv_ruleQualifiedName= ruleQualifiedName EOF
            {
             newCompositeNode(grammarAccess.getQualifiedNameRule()); 
            pushFollow(FOLLOW_1);
            iv_ruleQualifiedName=ruleQualifiedName();

            state._fsp--;

             current =iv_ruleQualifiedName.getText(); 
            match(input,EOF,FOLLOW_2); 

            }

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "entryRuleQualifiedName"


    // $ANTLR start "ruleQualifiedName"
    // InternalRsamlText.g:3971:1: ruleQualifiedName returns [AntlrDatatypeRuleToken current=new AntlrDatatypeRuleToken()] : ( (this_ID_0= RULE_ID | this_STRING_1= RULE_STRING ) (kw= '.' this_Name_3= ruleName )* ) ;
    public final AntlrDatatypeRuleToken ruleQualifiedName() throws RecognitionException {
        AntlrDatatypeRuleToken current = new AntlrDatatypeRuleToken();

        Token this_ID_0=null;
        Token this_STRING_1=null;
        Token kw=null;
        AntlrDatatypeRuleToken this_Name_3 = null;



        	enterRule();

        try {
            // InternalRsamlText.g:3977:2: ( ( (this_ID_0= RULE_ID | this_STRING_1= RULE_STRING ) (kw= '.' this_Name_3= ruleName )* ) )
            // InternalRsamlText.g:3978:2: ( (this_ID_0= RULE_ID | this_STRING_1= RULE_STRING ) (kw= '.' this_Name_3= ruleName )* )
            {
            // InternalRsamlText.g:3978:2: ( (this_ID_0= RULE_ID | this_STRING_1= RULE_STRING ) (kw= '.' this_Name_3= ruleName )* )
            // InternalRsamlText.g:3979:3: (this_ID_0= RULE_ID | this_STRING_1= RULE_STRING ) (kw= '.' this_Name_3= ruleName )*
            {
            // InternalRsamlText.g:3979:3: (this_ID_0= RULE_ID | this_STRING_1= RULE_STRING )
            int alt55=2;
            int LA55_0 = input.LA(1);

            if ( (LA55_0==RULE_ID) ) {
                alt55=1;
            }
            else if ( (LA55_0==RULE_STRING) ) {
                alt55=2;
            }
            else {
                NoViableAltException nvae =
                    new NoViableAltException("", 55, 0, input);

                throw nvae;
            }
            switch (alt55) {
                case 1 :
                    // InternalRsamlText.g:3980:4: this_ID_0= RULE_ID
                    {
                    this_ID_0=(Token)match(input,RULE_ID,FOLLOW_47); 

                    				current.merge(this_ID_0);
                    			

                    				newLeafNode(this_ID_0, grammarAccess.getQualifiedNameAccess().getIDTerminalRuleCall_0_0());
                    			

                    }
                    break;
                case 2 :
                    // InternalRsamlText.g:3988:4: this_STRING_1= RULE_STRING
                    {
                    this_STRING_1=(Token)match(input,RULE_STRING,FOLLOW_47); 

                    				current.merge(this_STRING_1);
                    			

                    				newLeafNode(this_STRING_1, grammarAccess.getQualifiedNameAccess().getSTRINGTerminalRuleCall_0_1());
                    			

                    }
                    break;

            }

            // InternalRsamlText.g:3996:3: (kw= '.' this_Name_3= ruleName )*
            loop56:
            do {
                int alt56=2;
                int LA56_0 = input.LA(1);

                if ( (LA56_0==81) ) {
                    alt56=1;
                }


                switch (alt56) {
            	case 1 :
            	    // InternalRsamlText.g:3997:4: kw= '.' this_Name_3= ruleName
            	    {
            	    kw=(Token)match(input,81,FOLLOW_48); 

            	    				current.merge(kw);
            	    				newLeafNode(kw, grammarAccess.getQualifiedNameAccess().getFullStopKeyword_1_0());
            	    			

            	    				newCompositeNode(grammarAccess.getQualifiedNameAccess().getNameParserRuleCall_1_1());
            	    			
            	    pushFollow(FOLLOW_47);
            	    this_Name_3=ruleName();

            	    state._fsp--;


            	    				current.merge(this_Name_3);
            	    			

            	    				afterParserOrEnumRuleCall();
            	    			

            	    }
            	    break;

            	default :
            	    break loop56;
                }
            } while (true);


            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "ruleQualifiedName"


    // $ANTLR start "entryRuleKeyword"
    // InternalRsamlText.g:4017:1: entryRuleKeyword returns [String current=null] : iv_ruleKeyword= ruleKeyword EOF ;
    public final String entryRuleKeyword() throws RecognitionException {
        String current = null;

        AntlrDatatypeRuleToken iv_ruleKeyword = null;


        try {
            // InternalRsamlText.g:4017:47: (iv_ruleKeyword= ruleKeyword EOF )
            // InternalRsamlText.g:4018:2: iv_ruleKeyword= ruleKeyword EOF
            {
             newCompositeNode(grammarAccess.getKeywordRule()); 
            pushFollow(FOLLOW_1);
            iv_ruleKeyword=ruleKeyword();

            state._fsp--;

             current =iv_ruleKeyword.getText(); 
            match(input,EOF,FOLLOW_2); 

            }

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "entryRuleKeyword"


    // $ANTLR start "ruleKeyword"
    // InternalRsamlText.g:4024:1: ruleKeyword returns [AntlrDatatypeRuleToken current=new AntlrDatatypeRuleToken()] : (kw= 'architecture' | kw= 'layer' | kw= 'module' | kw= 'function' | kw= 'action' | kw= 'rtAction' | kw= 'input' | kw= 'output' | kw= 'connect' | kw= 'inhibitor' | kw= 'suppressor' | kw= 'sensor' | kw= 'actuator' | kw= 'mission' | kw= 'goal' | kw= 'plan' | kw= 'activity' | kw= 'supervisor' | kw= 'order' | kw= 'database' | kw= 'knowledge' | kw= 'processor' | kw= 'latency' | kw= 'description' | kw= 'category' | kw= 'declaredLayers' | kw= 'unit' | kw= 'type' | kw= 'execType' | kw= 'period' | kw= 'deadline' | kw= 'wcet' | kw= 'level' | kw= 'maxExecTime' | kw= 'sensors' | kw= 'actuators' | kw= 'synchroType' | kw= 'schedPolicy' | kw= 'otherPolicy' | kw= 'start' | kw= 'dataType' | kw= 'messageType' | kw= 'topic' | kw= 'trigger' | kw= 'target' | kw= 'duration' | kw= 'kind' | kw= 'priority' | kw= 'achieves' | kw= 'actions' | kw= 'plans' | kw= 'realisedBy' | kw= 'issuer' | kw= 'receiver' | kw= 'requests' | kw= 'usedBy' | kw= 'core' | kw= 'modules' | kw= 'from' | kw= 'to' | kw= 'via' | kw= 'maxLatency' | kw= 'host' | kw= 'linkLatency' | kw= 'lifecycle' | kw= 'packages' | kw= 'centralized' | kw= 'hierarchical' | kw= 'behavioral' | kw= 'hybrid' | kw= 'other' | kw= 'simple' | kw= 'realTime' | kw= 'periodic' | kw= 'sporadic' | kw= 'aperiodic' | kw= 'ns' | kw= 'us' | kw= 'ms' | kw= 's' | kw= 'synchronous' | kw= 'asynchronous' | kw= 'FIFO' | kw= 'SJF' | kw= 'RR' | kw= 'RM' | kw= 'DM' | kw= 'EDF' | kw= 'LLF' | kw= 'OTHER' | kw= 'numeric' | kw= 'alphanumeric' | kw= 'boolean' | kw= 'structured' | kw= 'reactionTime' | kw= 'dataAge' | kw= 'plain' | kw= 'managed' | kw= 'single' | kw= 'perLayer' | kw= 'perProcessor' | kw= 'NaN' | kw= 'Infinity' ) ;
    public final AntlrDatatypeRuleToken ruleKeyword() throws RecognitionException {
        AntlrDatatypeRuleToken current = new AntlrDatatypeRuleToken();

        Token kw=null;


        	enterRule();

        try {
            // InternalRsamlText.g:4030:2: ( (kw= 'architecture' | kw= 'layer' | kw= 'module' | kw= 'function' | kw= 'action' | kw= 'rtAction' | kw= 'input' | kw= 'output' | kw= 'connect' | kw= 'inhibitor' | kw= 'suppressor' | kw= 'sensor' | kw= 'actuator' | kw= 'mission' | kw= 'goal' | kw= 'plan' | kw= 'activity' | kw= 'supervisor' | kw= 'order' | kw= 'database' | kw= 'knowledge' | kw= 'processor' | kw= 'latency' | kw= 'description' | kw= 'category' | kw= 'declaredLayers' | kw= 'unit' | kw= 'type' | kw= 'execType' | kw= 'period' | kw= 'deadline' | kw= 'wcet' | kw= 'level' | kw= 'maxExecTime' | kw= 'sensors' | kw= 'actuators' | kw= 'synchroType' | kw= 'schedPolicy' | kw= 'otherPolicy' | kw= 'start' | kw= 'dataType' | kw= 'messageType' | kw= 'topic' | kw= 'trigger' | kw= 'target' | kw= 'duration' | kw= 'kind' | kw= 'priority' | kw= 'achieves' | kw= 'actions' | kw= 'plans' | kw= 'realisedBy' | kw= 'issuer' | kw= 'receiver' | kw= 'requests' | kw= 'usedBy' | kw= 'core' | kw= 'modules' | kw= 'from' | kw= 'to' | kw= 'via' | kw= 'maxLatency' | kw= 'host' | kw= 'linkLatency' | kw= 'lifecycle' | kw= 'packages' | kw= 'centralized' | kw= 'hierarchical' | kw= 'behavioral' | kw= 'hybrid' | kw= 'other' | kw= 'simple' | kw= 'realTime' | kw= 'periodic' | kw= 'sporadic' | kw= 'aperiodic' | kw= 'ns' | kw= 'us' | kw= 'ms' | kw= 's' | kw= 'synchronous' | kw= 'asynchronous' | kw= 'FIFO' | kw= 'SJF' | kw= 'RR' | kw= 'RM' | kw= 'DM' | kw= 'EDF' | kw= 'LLF' | kw= 'OTHER' | kw= 'numeric' | kw= 'alphanumeric' | kw= 'boolean' | kw= 'structured' | kw= 'reactionTime' | kw= 'dataAge' | kw= 'plain' | kw= 'managed' | kw= 'single' | kw= 'perLayer' | kw= 'perProcessor' | kw= 'NaN' | kw= 'Infinity' ) )
            // InternalRsamlText.g:4031:2: (kw= 'architecture' | kw= 'layer' | kw= 'module' | kw= 'function' | kw= 'action' | kw= 'rtAction' | kw= 'input' | kw= 'output' | kw= 'connect' | kw= 'inhibitor' | kw= 'suppressor' | kw= 'sensor' | kw= 'actuator' | kw= 'mission' | kw= 'goal' | kw= 'plan' | kw= 'activity' | kw= 'supervisor' | kw= 'order' | kw= 'database' | kw= 'knowledge' | kw= 'processor' | kw= 'latency' | kw= 'description' | kw= 'category' | kw= 'declaredLayers' | kw= 'unit' | kw= 'type' | kw= 'execType' | kw= 'period' | kw= 'deadline' | kw= 'wcet' | kw= 'level' | kw= 'maxExecTime' | kw= 'sensors' | kw= 'actuators' | kw= 'synchroType' | kw= 'schedPolicy' | kw= 'otherPolicy' | kw= 'start' | kw= 'dataType' | kw= 'messageType' | kw= 'topic' | kw= 'trigger' | kw= 'target' | kw= 'duration' | kw= 'kind' | kw= 'priority' | kw= 'achieves' | kw= 'actions' | kw= 'plans' | kw= 'realisedBy' | kw= 'issuer' | kw= 'receiver' | kw= 'requests' | kw= 'usedBy' | kw= 'core' | kw= 'modules' | kw= 'from' | kw= 'to' | kw= 'via' | kw= 'maxLatency' | kw= 'host' | kw= 'linkLatency' | kw= 'lifecycle' | kw= 'packages' | kw= 'centralized' | kw= 'hierarchical' | kw= 'behavioral' | kw= 'hybrid' | kw= 'other' | kw= 'simple' | kw= 'realTime' | kw= 'periodic' | kw= 'sporadic' | kw= 'aperiodic' | kw= 'ns' | kw= 'us' | kw= 'ms' | kw= 's' | kw= 'synchronous' | kw= 'asynchronous' | kw= 'FIFO' | kw= 'SJF' | kw= 'RR' | kw= 'RM' | kw= 'DM' | kw= 'EDF' | kw= 'LLF' | kw= 'OTHER' | kw= 'numeric' | kw= 'alphanumeric' | kw= 'boolean' | kw= 'structured' | kw= 'reactionTime' | kw= 'dataAge' | kw= 'plain' | kw= 'managed' | kw= 'single' | kw= 'perLayer' | kw= 'perProcessor' | kw= 'NaN' | kw= 'Infinity' )
            {
            // InternalRsamlText.g:4031:2: (kw= 'architecture' | kw= 'layer' | kw= 'module' | kw= 'function' | kw= 'action' | kw= 'rtAction' | kw= 'input' | kw= 'output' | kw= 'connect' | kw= 'inhibitor' | kw= 'suppressor' | kw= 'sensor' | kw= 'actuator' | kw= 'mission' | kw= 'goal' | kw= 'plan' | kw= 'activity' | kw= 'supervisor' | kw= 'order' | kw= 'database' | kw= 'knowledge' | kw= 'processor' | kw= 'latency' | kw= 'description' | kw= 'category' | kw= 'declaredLayers' | kw= 'unit' | kw= 'type' | kw= 'execType' | kw= 'period' | kw= 'deadline' | kw= 'wcet' | kw= 'level' | kw= 'maxExecTime' | kw= 'sensors' | kw= 'actuators' | kw= 'synchroType' | kw= 'schedPolicy' | kw= 'otherPolicy' | kw= 'start' | kw= 'dataType' | kw= 'messageType' | kw= 'topic' | kw= 'trigger' | kw= 'target' | kw= 'duration' | kw= 'kind' | kw= 'priority' | kw= 'achieves' | kw= 'actions' | kw= 'plans' | kw= 'realisedBy' | kw= 'issuer' | kw= 'receiver' | kw= 'requests' | kw= 'usedBy' | kw= 'core' | kw= 'modules' | kw= 'from' | kw= 'to' | kw= 'via' | kw= 'maxLatency' | kw= 'host' | kw= 'linkLatency' | kw= 'lifecycle' | kw= 'packages' | kw= 'centralized' | kw= 'hierarchical' | kw= 'behavioral' | kw= 'hybrid' | kw= 'other' | kw= 'simple' | kw= 'realTime' | kw= 'periodic' | kw= 'sporadic' | kw= 'aperiodic' | kw= 'ns' | kw= 'us' | kw= 'ms' | kw= 's' | kw= 'synchronous' | kw= 'asynchronous' | kw= 'FIFO' | kw= 'SJF' | kw= 'RR' | kw= 'RM' | kw= 'DM' | kw= 'EDF' | kw= 'LLF' | kw= 'OTHER' | kw= 'numeric' | kw= 'alphanumeric' | kw= 'boolean' | kw= 'structured' | kw= 'reactionTime' | kw= 'dataAge' | kw= 'plain' | kw= 'managed' | kw= 'single' | kw= 'perLayer' | kw= 'perProcessor' | kw= 'NaN' | kw= 'Infinity' )
            int alt57=103;
            switch ( input.LA(1) ) {
            case 11:
                {
                alt57=1;
                }
                break;
            case 25:
                {
                alt57=2;
                }
                break;
            case 28:
                {
                alt57=3;
                }
                break;
            case 32:
                {
                alt57=4;
                }
                break;
            case 36:
                {
                alt57=5;
                }
                break;
            case 37:
                {
                alt57=6;
                }
                break;
            case 39:
                {
                alt57=7;
                }
                break;
            case 40:
                {
                alt57=8;
                }
                break;
            case 44:
                {
                alt57=9;
                }
                break;
            case 46:
                {
                alt57=10;
                }
                break;
            case 50:
                {
                alt57=11;
                }
                break;
            case 51:
                {
                alt57=12;
                }
                break;
            case 53:
                {
                alt57=13;
                }
                break;
            case 54:
                {
                alt57=14;
                }
                break;
            case 55:
                {
                alt57=15;
                }
                break;
            case 57:
                {
                alt57=16;
                }
                break;
            case 59:
                {
                alt57=17;
                }
                break;
            case 61:
                {
                alt57=18;
                }
                break;
            case 64:
                {
                alt57=19;
                }
                break;
            case 68:
                {
                alt57=20;
                }
                break;
            case 69:
                {
                alt57=21;
                }
                break;
            case 71:
                {
                alt57=22;
                }
                break;
            case 76:
                {
                alt57=23;
                }
                break;
            case 18:
                {
                alt57=24;
                }
                break;
            case 13:
                {
                alt57=25;
                }
                break;
            case 14:
                {
                alt57=26;
                }
                break;
            case 19:
                {
                alt57=27;
                }
                break;
            case 20:
                {
                alt57=28;
                }
                break;
            case 21:
                {
                alt57=29;
                }
                break;
            case 22:
                {
                alt57=30;
                }
                break;
            case 23:
                {
                alt57=31;
                }
                break;
            case 24:
                {
                alt57=32;
                }
                break;
            case 26:
                {
                alt57=33;
                }
                break;
            case 27:
                {
                alt57=34;
                }
                break;
            case 29:
                {
                alt57=35;
                }
                break;
            case 31:
                {
                alt57=36;
                }
                break;
            case 33:
                {
                alt57=37;
                }
                break;
            case 34:
                {
                alt57=38;
                }
                break;
            case 35:
                {
                alt57=39;
                }
                break;
            case 38:
                {
                alt57=40;
                }
                break;
            case 41:
                {
                alt57=41;
                }
                break;
            case 42:
                {
                alt57=42;
                }
                break;
            case 43:
                {
                alt57=43;
                }
                break;
            case 47:
                {
                alt57=44;
                }
                break;
            case 48:
                {
                alt57=45;
                }
                break;
            case 49:
                {
                alt57=46;
                }
                break;
            case 52:
                {
                alt57=47;
                }
                break;
            case 56:
                {
                alt57=48;
                }
                break;
            case 58:
                {
                alt57=49;
                }
                break;
            case 60:
                {
                alt57=50;
                }
                break;
            case 62:
                {
                alt57=51;
                }
                break;
            case 63:
                {
                alt57=52;
                }
                break;
            case 65:
                {
                alt57=53;
                }
                break;
            case 66:
                {
                alt57=54;
                }
                break;
            case 67:
                {
                alt57=55;
                }
                break;
            case 70:
                {
                alt57=56;
                }
                break;
            case 72:
                {
                alt57=57;
                }
                break;
            case 75:
                {
                alt57=58;
                }
                break;
            case 77:
                {
                alt57=59;
                }
                break;
            case 78:
                {
                alt57=60;
                }
                break;
            case 79:
                {
                alt57=61;
                }
                break;
            case 80:
                {
                alt57=62;
                }
                break;
            case 73:
                {
                alt57=63;
                }
                break;
            case 74:
                {
                alt57=64;
                }
                break;
            case 15:
                {
                alt57=65;
                }
                break;
            case 16:
                {
                alt57=66;
                }
                break;
            case 82:
                {
                alt57=67;
                }
                break;
            case 83:
                {
                alt57=68;
                }
                break;
            case 84:
                {
                alt57=69;
                }
                break;
            case 85:
                {
                alt57=70;
                }
                break;
            case 86:
                {
                alt57=71;
                }
                break;
            case 87:
                {
                alt57=72;
                }
                break;
            case 88:
                {
                alt57=73;
                }
                break;
            case 89:
                {
                alt57=74;
                }
                break;
            case 90:
                {
                alt57=75;
                }
                break;
            case 91:
                {
                alt57=76;
                }
                break;
            case 92:
                {
                alt57=77;
                }
                break;
            case 93:
                {
                alt57=78;
                }
                break;
            case 94:
                {
                alt57=79;
                }
                break;
            case 95:
                {
                alt57=80;
                }
                break;
            case 96:
                {
                alt57=81;
                }
                break;
            case 97:
                {
                alt57=82;
                }
                break;
            case 98:
                {
                alt57=83;
                }
                break;
            case 99:
                {
                alt57=84;
                }
                break;
            case 100:
                {
                alt57=85;
                }
                break;
            case 101:
                {
                alt57=86;
                }
                break;
            case 102:
                {
                alt57=87;
                }
                break;
            case 103:
                {
                alt57=88;
                }
                break;
            case 104:
                {
                alt57=89;
                }
                break;
            case 105:
                {
                alt57=90;
                }
                break;
            case 106:
                {
                alt57=91;
                }
                break;
            case 107:
                {
                alt57=92;
                }
                break;
            case 108:
                {
                alt57=93;
                }
                break;
            case 109:
                {
                alt57=94;
                }
                break;
            case 110:
                {
                alt57=95;
                }
                break;
            case 111:
                {
                alt57=96;
                }
                break;
            case 112:
                {
                alt57=97;
                }
                break;
            case 113:
                {
                alt57=98;
                }
                break;
            case 114:
                {
                alt57=99;
                }
                break;
            case 115:
                {
                alt57=100;
                }
                break;
            case 116:
                {
                alt57=101;
                }
                break;
            case 117:
                {
                alt57=102;
                }
                break;
            case 118:
                {
                alt57=103;
                }
                break;
            default:
                NoViableAltException nvae =
                    new NoViableAltException("", 57, 0, input);

                throw nvae;
            }

            switch (alt57) {
                case 1 :
                    // InternalRsamlText.g:4032:3: kw= 'architecture'
                    {
                    kw=(Token)match(input,11,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getArchitectureKeyword_0());
                    		

                    }
                    break;
                case 2 :
                    // InternalRsamlText.g:4038:3: kw= 'layer'
                    {
                    kw=(Token)match(input,25,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getLayerKeyword_1());
                    		

                    }
                    break;
                case 3 :
                    // InternalRsamlText.g:4044:3: kw= 'module'
                    {
                    kw=(Token)match(input,28,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getModuleKeyword_2());
                    		

                    }
                    break;
                case 4 :
                    // InternalRsamlText.g:4050:3: kw= 'function'
                    {
                    kw=(Token)match(input,32,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getFunctionKeyword_3());
                    		

                    }
                    break;
                case 5 :
                    // InternalRsamlText.g:4056:3: kw= 'action'
                    {
                    kw=(Token)match(input,36,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getActionKeyword_4());
                    		

                    }
                    break;
                case 6 :
                    // InternalRsamlText.g:4062:3: kw= 'rtAction'
                    {
                    kw=(Token)match(input,37,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getRtActionKeyword_5());
                    		

                    }
                    break;
                case 7 :
                    // InternalRsamlText.g:4068:3: kw= 'input'
                    {
                    kw=(Token)match(input,39,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getInputKeyword_6());
                    		

                    }
                    break;
                case 8 :
                    // InternalRsamlText.g:4074:3: kw= 'output'
                    {
                    kw=(Token)match(input,40,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getOutputKeyword_7());
                    		

                    }
                    break;
                case 9 :
                    // InternalRsamlText.g:4080:3: kw= 'connect'
                    {
                    kw=(Token)match(input,44,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getConnectKeyword_8());
                    		

                    }
                    break;
                case 10 :
                    // InternalRsamlText.g:4086:3: kw= 'inhibitor'
                    {
                    kw=(Token)match(input,46,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getInhibitorKeyword_9());
                    		

                    }
                    break;
                case 11 :
                    // InternalRsamlText.g:4092:3: kw= 'suppressor'
                    {
                    kw=(Token)match(input,50,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getSuppressorKeyword_10());
                    		

                    }
                    break;
                case 12 :
                    // InternalRsamlText.g:4098:3: kw= 'sensor'
                    {
                    kw=(Token)match(input,51,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getSensorKeyword_11());
                    		

                    }
                    break;
                case 13 :
                    // InternalRsamlText.g:4104:3: kw= 'actuator'
                    {
                    kw=(Token)match(input,53,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getActuatorKeyword_12());
                    		

                    }
                    break;
                case 14 :
                    // InternalRsamlText.g:4110:3: kw= 'mission'
                    {
                    kw=(Token)match(input,54,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getMissionKeyword_13());
                    		

                    }
                    break;
                case 15 :
                    // InternalRsamlText.g:4116:3: kw= 'goal'
                    {
                    kw=(Token)match(input,55,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getGoalKeyword_14());
                    		

                    }
                    break;
                case 16 :
                    // InternalRsamlText.g:4122:3: kw= 'plan'
                    {
                    kw=(Token)match(input,57,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getPlanKeyword_15());
                    		

                    }
                    break;
                case 17 :
                    // InternalRsamlText.g:4128:3: kw= 'activity'
                    {
                    kw=(Token)match(input,59,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getActivityKeyword_16());
                    		

                    }
                    break;
                case 18 :
                    // InternalRsamlText.g:4134:3: kw= 'supervisor'
                    {
                    kw=(Token)match(input,61,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getSupervisorKeyword_17());
                    		

                    }
                    break;
                case 19 :
                    // InternalRsamlText.g:4140:3: kw= 'order'
                    {
                    kw=(Token)match(input,64,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getOrderKeyword_18());
                    		

                    }
                    break;
                case 20 :
                    // InternalRsamlText.g:4146:3: kw= 'database'
                    {
                    kw=(Token)match(input,68,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getDatabaseKeyword_19());
                    		

                    }
                    break;
                case 21 :
                    // InternalRsamlText.g:4152:3: kw= 'knowledge'
                    {
                    kw=(Token)match(input,69,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getKnowledgeKeyword_20());
                    		

                    }
                    break;
                case 22 :
                    // InternalRsamlText.g:4158:3: kw= 'processor'
                    {
                    kw=(Token)match(input,71,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getProcessorKeyword_21());
                    		

                    }
                    break;
                case 23 :
                    // InternalRsamlText.g:4164:3: kw= 'latency'
                    {
                    kw=(Token)match(input,76,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getLatencyKeyword_22());
                    		

                    }
                    break;
                case 24 :
                    // InternalRsamlText.g:4170:3: kw= 'description'
                    {
                    kw=(Token)match(input,18,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getDescriptionKeyword_23());
                    		

                    }
                    break;
                case 25 :
                    // InternalRsamlText.g:4176:3: kw= 'category'
                    {
                    kw=(Token)match(input,13,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getCategoryKeyword_24());
                    		

                    }
                    break;
                case 26 :
                    // InternalRsamlText.g:4182:3: kw= 'declaredLayers'
                    {
                    kw=(Token)match(input,14,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getDeclaredLayersKeyword_25());
                    		

                    }
                    break;
                case 27 :
                    // InternalRsamlText.g:4188:3: kw= 'unit'
                    {
                    kw=(Token)match(input,19,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getUnitKeyword_26());
                    		

                    }
                    break;
                case 28 :
                    // InternalRsamlText.g:4194:3: kw= 'type'
                    {
                    kw=(Token)match(input,20,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getTypeKeyword_27());
                    		

                    }
                    break;
                case 29 :
                    // InternalRsamlText.g:4200:3: kw= 'execType'
                    {
                    kw=(Token)match(input,21,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getExecTypeKeyword_28());
                    		

                    }
                    break;
                case 30 :
                    // InternalRsamlText.g:4206:3: kw= 'period'
                    {
                    kw=(Token)match(input,22,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getPeriodKeyword_29());
                    		

                    }
                    break;
                case 31 :
                    // InternalRsamlText.g:4212:3: kw= 'deadline'
                    {
                    kw=(Token)match(input,23,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getDeadlineKeyword_30());
                    		

                    }
                    break;
                case 32 :
                    // InternalRsamlText.g:4218:3: kw= 'wcet'
                    {
                    kw=(Token)match(input,24,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getWcetKeyword_31());
                    		

                    }
                    break;
                case 33 :
                    // InternalRsamlText.g:4224:3: kw= 'level'
                    {
                    kw=(Token)match(input,26,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getLevelKeyword_32());
                    		

                    }
                    break;
                case 34 :
                    // InternalRsamlText.g:4230:3: kw= 'maxExecTime'
                    {
                    kw=(Token)match(input,27,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getMaxExecTimeKeyword_33());
                    		

                    }
                    break;
                case 35 :
                    // InternalRsamlText.g:4236:3: kw= 'sensors'
                    {
                    kw=(Token)match(input,29,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getSensorsKeyword_34());
                    		

                    }
                    break;
                case 36 :
                    // InternalRsamlText.g:4242:3: kw= 'actuators'
                    {
                    kw=(Token)match(input,31,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getActuatorsKeyword_35());
                    		

                    }
                    break;
                case 37 :
                    // InternalRsamlText.g:4248:3: kw= 'synchroType'
                    {
                    kw=(Token)match(input,33,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getSynchroTypeKeyword_36());
                    		

                    }
                    break;
                case 38 :
                    // InternalRsamlText.g:4254:3: kw= 'schedPolicy'
                    {
                    kw=(Token)match(input,34,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getSchedPolicyKeyword_37());
                    		

                    }
                    break;
                case 39 :
                    // InternalRsamlText.g:4260:3: kw= 'otherPolicy'
                    {
                    kw=(Token)match(input,35,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getOtherPolicyKeyword_38());
                    		

                    }
                    break;
                case 40 :
                    // InternalRsamlText.g:4266:3: kw= 'start'
                    {
                    kw=(Token)match(input,38,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getStartKeyword_39());
                    		

                    }
                    break;
                case 41 :
                    // InternalRsamlText.g:4272:3: kw= 'dataType'
                    {
                    kw=(Token)match(input,41,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getDataTypeKeyword_40());
                    		

                    }
                    break;
                case 42 :
                    // InternalRsamlText.g:4278:3: kw= 'messageType'
                    {
                    kw=(Token)match(input,42,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getMessageTypeKeyword_41());
                    		

                    }
                    break;
                case 43 :
                    // InternalRsamlText.g:4284:3: kw= 'topic'
                    {
                    kw=(Token)match(input,43,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getTopicKeyword_42());
                    		

                    }
                    break;
                case 44 :
                    // InternalRsamlText.g:4290:3: kw= 'trigger'
                    {
                    kw=(Token)match(input,47,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getTriggerKeyword_43());
                    		

                    }
                    break;
                case 45 :
                    // InternalRsamlText.g:4296:3: kw= 'target'
                    {
                    kw=(Token)match(input,48,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getTargetKeyword_44());
                    		

                    }
                    break;
                case 46 :
                    // InternalRsamlText.g:4302:3: kw= 'duration'
                    {
                    kw=(Token)match(input,49,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getDurationKeyword_45());
                    		

                    }
                    break;
                case 47 :
                    // InternalRsamlText.g:4308:3: kw= 'kind'
                    {
                    kw=(Token)match(input,52,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getKindKeyword_46());
                    		

                    }
                    break;
                case 48 :
                    // InternalRsamlText.g:4314:3: kw= 'priority'
                    {
                    kw=(Token)match(input,56,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getPriorityKeyword_47());
                    		

                    }
                    break;
                case 49 :
                    // InternalRsamlText.g:4320:3: kw= 'achieves'
                    {
                    kw=(Token)match(input,58,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getAchievesKeyword_48());
                    		

                    }
                    break;
                case 50 :
                    // InternalRsamlText.g:4326:3: kw= 'actions'
                    {
                    kw=(Token)match(input,60,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getActionsKeyword_49());
                    		

                    }
                    break;
                case 51 :
                    // InternalRsamlText.g:4332:3: kw= 'plans'
                    {
                    kw=(Token)match(input,62,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getPlansKeyword_50());
                    		

                    }
                    break;
                case 52 :
                    // InternalRsamlText.g:4338:3: kw= 'realisedBy'
                    {
                    kw=(Token)match(input,63,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getRealisedByKeyword_51());
                    		

                    }
                    break;
                case 53 :
                    // InternalRsamlText.g:4344:3: kw= 'issuer'
                    {
                    kw=(Token)match(input,65,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getIssuerKeyword_52());
                    		

                    }
                    break;
                case 54 :
                    // InternalRsamlText.g:4350:3: kw= 'receiver'
                    {
                    kw=(Token)match(input,66,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getReceiverKeyword_53());
                    		

                    }
                    break;
                case 55 :
                    // InternalRsamlText.g:4356:3: kw= 'requests'
                    {
                    kw=(Token)match(input,67,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getRequestsKeyword_54());
                    		

                    }
                    break;
                case 56 :
                    // InternalRsamlText.g:4362:3: kw= 'usedBy'
                    {
                    kw=(Token)match(input,70,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getUsedByKeyword_55());
                    		

                    }
                    break;
                case 57 :
                    // InternalRsamlText.g:4368:3: kw= 'core'
                    {
                    kw=(Token)match(input,72,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getCoreKeyword_56());
                    		

                    }
                    break;
                case 58 :
                    // InternalRsamlText.g:4374:3: kw= 'modules'
                    {
                    kw=(Token)match(input,75,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getModulesKeyword_57());
                    		

                    }
                    break;
                case 59 :
                    // InternalRsamlText.g:4380:3: kw= 'from'
                    {
                    kw=(Token)match(input,77,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getFromKeyword_58());
                    		

                    }
                    break;
                case 60 :
                    // InternalRsamlText.g:4386:3: kw= 'to'
                    {
                    kw=(Token)match(input,78,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getToKeyword_59());
                    		

                    }
                    break;
                case 61 :
                    // InternalRsamlText.g:4392:3: kw= 'via'
                    {
                    kw=(Token)match(input,79,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getViaKeyword_60());
                    		

                    }
                    break;
                case 62 :
                    // InternalRsamlText.g:4398:3: kw= 'maxLatency'
                    {
                    kw=(Token)match(input,80,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getMaxLatencyKeyword_61());
                    		

                    }
                    break;
                case 63 :
                    // InternalRsamlText.g:4404:3: kw= 'host'
                    {
                    kw=(Token)match(input,73,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getHostKeyword_62());
                    		

                    }
                    break;
                case 64 :
                    // InternalRsamlText.g:4410:3: kw= 'linkLatency'
                    {
                    kw=(Token)match(input,74,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getLinkLatencyKeyword_63());
                    		

                    }
                    break;
                case 65 :
                    // InternalRsamlText.g:4416:3: kw= 'lifecycle'
                    {
                    kw=(Token)match(input,15,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getLifecycleKeyword_64());
                    		

                    }
                    break;
                case 66 :
                    // InternalRsamlText.g:4422:3: kw= 'packages'
                    {
                    kw=(Token)match(input,16,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getPackagesKeyword_65());
                    		

                    }
                    break;
                case 67 :
                    // InternalRsamlText.g:4428:3: kw= 'centralized'
                    {
                    kw=(Token)match(input,82,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getCentralizedKeyword_66());
                    		

                    }
                    break;
                case 68 :
                    // InternalRsamlText.g:4434:3: kw= 'hierarchical'
                    {
                    kw=(Token)match(input,83,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getHierarchicalKeyword_67());
                    		

                    }
                    break;
                case 69 :
                    // InternalRsamlText.g:4440:3: kw= 'behavioral'
                    {
                    kw=(Token)match(input,84,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getBehavioralKeyword_68());
                    		

                    }
                    break;
                case 70 :
                    // InternalRsamlText.g:4446:3: kw= 'hybrid'
                    {
                    kw=(Token)match(input,85,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getHybridKeyword_69());
                    		

                    }
                    break;
                case 71 :
                    // InternalRsamlText.g:4452:3: kw= 'other'
                    {
                    kw=(Token)match(input,86,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getOtherKeyword_70());
                    		

                    }
                    break;
                case 72 :
                    // InternalRsamlText.g:4458:3: kw= 'simple'
                    {
                    kw=(Token)match(input,87,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getSimpleKeyword_71());
                    		

                    }
                    break;
                case 73 :
                    // InternalRsamlText.g:4464:3: kw= 'realTime'
                    {
                    kw=(Token)match(input,88,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getRealTimeKeyword_72());
                    		

                    }
                    break;
                case 74 :
                    // InternalRsamlText.g:4470:3: kw= 'periodic'
                    {
                    kw=(Token)match(input,89,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getPeriodicKeyword_73());
                    		

                    }
                    break;
                case 75 :
                    // InternalRsamlText.g:4476:3: kw= 'sporadic'
                    {
                    kw=(Token)match(input,90,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getSporadicKeyword_74());
                    		

                    }
                    break;
                case 76 :
                    // InternalRsamlText.g:4482:3: kw= 'aperiodic'
                    {
                    kw=(Token)match(input,91,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getAperiodicKeyword_75());
                    		

                    }
                    break;
                case 77 :
                    // InternalRsamlText.g:4488:3: kw= 'ns'
                    {
                    kw=(Token)match(input,92,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getNsKeyword_76());
                    		

                    }
                    break;
                case 78 :
                    // InternalRsamlText.g:4494:3: kw= 'us'
                    {
                    kw=(Token)match(input,93,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getUsKeyword_77());
                    		

                    }
                    break;
                case 79 :
                    // InternalRsamlText.g:4500:3: kw= 'ms'
                    {
                    kw=(Token)match(input,94,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getMsKeyword_78());
                    		

                    }
                    break;
                case 80 :
                    // InternalRsamlText.g:4506:3: kw= 's'
                    {
                    kw=(Token)match(input,95,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getSKeyword_79());
                    		

                    }
                    break;
                case 81 :
                    // InternalRsamlText.g:4512:3: kw= 'synchronous'
                    {
                    kw=(Token)match(input,96,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getSynchronousKeyword_80());
                    		

                    }
                    break;
                case 82 :
                    // InternalRsamlText.g:4518:3: kw= 'asynchronous'
                    {
                    kw=(Token)match(input,97,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getAsynchronousKeyword_81());
                    		

                    }
                    break;
                case 83 :
                    // InternalRsamlText.g:4524:3: kw= 'FIFO'
                    {
                    kw=(Token)match(input,98,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getFIFOKeyword_82());
                    		

                    }
                    break;
                case 84 :
                    // InternalRsamlText.g:4530:3: kw= 'SJF'
                    {
                    kw=(Token)match(input,99,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getSJFKeyword_83());
                    		

                    }
                    break;
                case 85 :
                    // InternalRsamlText.g:4536:3: kw= 'RR'
                    {
                    kw=(Token)match(input,100,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getRRKeyword_84());
                    		

                    }
                    break;
                case 86 :
                    // InternalRsamlText.g:4542:3: kw= 'RM'
                    {
                    kw=(Token)match(input,101,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getRMKeyword_85());
                    		

                    }
                    break;
                case 87 :
                    // InternalRsamlText.g:4548:3: kw= 'DM'
                    {
                    kw=(Token)match(input,102,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getDMKeyword_86());
                    		

                    }
                    break;
                case 88 :
                    // InternalRsamlText.g:4554:3: kw= 'EDF'
                    {
                    kw=(Token)match(input,103,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getEDFKeyword_87());
                    		

                    }
                    break;
                case 89 :
                    // InternalRsamlText.g:4560:3: kw= 'LLF'
                    {
                    kw=(Token)match(input,104,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getLLFKeyword_88());
                    		

                    }
                    break;
                case 90 :
                    // InternalRsamlText.g:4566:3: kw= 'OTHER'
                    {
                    kw=(Token)match(input,105,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getOTHERKeyword_89());
                    		

                    }
                    break;
                case 91 :
                    // InternalRsamlText.g:4572:3: kw= 'numeric'
                    {
                    kw=(Token)match(input,106,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getNumericKeyword_90());
                    		

                    }
                    break;
                case 92 :
                    // InternalRsamlText.g:4578:3: kw= 'alphanumeric'
                    {
                    kw=(Token)match(input,107,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getAlphanumericKeyword_91());
                    		

                    }
                    break;
                case 93 :
                    // InternalRsamlText.g:4584:3: kw= 'boolean'
                    {
                    kw=(Token)match(input,108,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getBooleanKeyword_92());
                    		

                    }
                    break;
                case 94 :
                    // InternalRsamlText.g:4590:3: kw= 'structured'
                    {
                    kw=(Token)match(input,109,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getStructuredKeyword_93());
                    		

                    }
                    break;
                case 95 :
                    // InternalRsamlText.g:4596:3: kw= 'reactionTime'
                    {
                    kw=(Token)match(input,110,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getReactionTimeKeyword_94());
                    		

                    }
                    break;
                case 96 :
                    // InternalRsamlText.g:4602:3: kw= 'dataAge'
                    {
                    kw=(Token)match(input,111,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getDataAgeKeyword_95());
                    		

                    }
                    break;
                case 97 :
                    // InternalRsamlText.g:4608:3: kw= 'plain'
                    {
                    kw=(Token)match(input,112,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getPlainKeyword_96());
                    		

                    }
                    break;
                case 98 :
                    // InternalRsamlText.g:4614:3: kw= 'managed'
                    {
                    kw=(Token)match(input,113,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getManagedKeyword_97());
                    		

                    }
                    break;
                case 99 :
                    // InternalRsamlText.g:4620:3: kw= 'single'
                    {
                    kw=(Token)match(input,114,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getSingleKeyword_98());
                    		

                    }
                    break;
                case 100 :
                    // InternalRsamlText.g:4626:3: kw= 'perLayer'
                    {
                    kw=(Token)match(input,115,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getPerLayerKeyword_99());
                    		

                    }
                    break;
                case 101 :
                    // InternalRsamlText.g:4632:3: kw= 'perProcessor'
                    {
                    kw=(Token)match(input,116,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getPerProcessorKeyword_100());
                    		

                    }
                    break;
                case 102 :
                    // InternalRsamlText.g:4638:3: kw= 'NaN'
                    {
                    kw=(Token)match(input,117,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getNaNKeyword_101());
                    		

                    }
                    break;
                case 103 :
                    // InternalRsamlText.g:4644:3: kw= 'Infinity'
                    {
                    kw=(Token)match(input,118,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getKeywordAccess().getInfinityKeyword_102());
                    		

                    }
                    break;

            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "ruleKeyword"


    // $ANTLR start "entryRuleReal"
    // InternalRsamlText.g:4653:1: entryRuleReal returns [String current=null] : iv_ruleReal= ruleReal EOF ;
    public final String entryRuleReal() throws RecognitionException {
        String current = null;

        AntlrDatatypeRuleToken iv_ruleReal = null;


        try {
            // InternalRsamlText.g:4653:44: (iv_ruleReal= ruleReal EOF )
            // InternalRsamlText.g:4654:2: iv_ruleReal= ruleReal EOF
            {
             newCompositeNode(grammarAccess.getRealRule()); 
            pushFollow(FOLLOW_1);
            iv_ruleReal=ruleReal();

            state._fsp--;

             current =iv_ruleReal.getText(); 
            match(input,EOF,FOLLOW_2); 

            }

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "entryRuleReal"


    // $ANTLR start "ruleReal"
    // InternalRsamlText.g:4660:1: ruleReal returns [AntlrDatatypeRuleToken current=new AntlrDatatypeRuleToken()] : (this_NUMBER_0= RULE_NUMBER | kw= 'NaN' | kw= 'Infinity' | (kw= '-' kw= 'Infinity' ) ) ;
    public final AntlrDatatypeRuleToken ruleReal() throws RecognitionException {
        AntlrDatatypeRuleToken current = new AntlrDatatypeRuleToken();

        Token this_NUMBER_0=null;
        Token kw=null;


        	enterRule();

        try {
            // InternalRsamlText.g:4666:2: ( (this_NUMBER_0= RULE_NUMBER | kw= 'NaN' | kw= 'Infinity' | (kw= '-' kw= 'Infinity' ) ) )
            // InternalRsamlText.g:4667:2: (this_NUMBER_0= RULE_NUMBER | kw= 'NaN' | kw= 'Infinity' | (kw= '-' kw= 'Infinity' ) )
            {
            // InternalRsamlText.g:4667:2: (this_NUMBER_0= RULE_NUMBER | kw= 'NaN' | kw= 'Infinity' | (kw= '-' kw= 'Infinity' ) )
            int alt58=4;
            switch ( input.LA(1) ) {
            case RULE_NUMBER:
                {
                alt58=1;
                }
                break;
            case 117:
                {
                alt58=2;
                }
                break;
            case 118:
                {
                alt58=3;
                }
                break;
            case 119:
                {
                alt58=4;
                }
                break;
            default:
                NoViableAltException nvae =
                    new NoViableAltException("", 58, 0, input);

                throw nvae;
            }

            switch (alt58) {
                case 1 :
                    // InternalRsamlText.g:4668:3: this_NUMBER_0= RULE_NUMBER
                    {
                    this_NUMBER_0=(Token)match(input,RULE_NUMBER,FOLLOW_2); 

                    			current.merge(this_NUMBER_0);
                    		

                    			newLeafNode(this_NUMBER_0, grammarAccess.getRealAccess().getNUMBERTerminalRuleCall_0());
                    		

                    }
                    break;
                case 2 :
                    // InternalRsamlText.g:4676:3: kw= 'NaN'
                    {
                    kw=(Token)match(input,117,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getRealAccess().getNaNKeyword_1());
                    		

                    }
                    break;
                case 3 :
                    // InternalRsamlText.g:4682:3: kw= 'Infinity'
                    {
                    kw=(Token)match(input,118,FOLLOW_2); 

                    			current.merge(kw);
                    			newLeafNode(kw, grammarAccess.getRealAccess().getInfinityKeyword_2());
                    		

                    }
                    break;
                case 4 :
                    // InternalRsamlText.g:4688:3: (kw= '-' kw= 'Infinity' )
                    {
                    // InternalRsamlText.g:4688:3: (kw= '-' kw= 'Infinity' )
                    // InternalRsamlText.g:4689:4: kw= '-' kw= 'Infinity'
                    {
                    kw=(Token)match(input,119,FOLLOW_49); 

                    				current.merge(kw);
                    				newLeafNode(kw, grammarAccess.getRealAccess().getHyphenMinusKeyword_3_0());
                    			
                    kw=(Token)match(input,118,FOLLOW_2); 

                    				current.merge(kw);
                    				newLeafNode(kw, grammarAccess.getRealAccess().getInfinityKeyword_3_1());
                    			

                    }


                    }
                    break;

            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "ruleReal"


    // $ANTLR start "entryRuleInteger"
    // InternalRsamlText.g:4704:1: entryRuleInteger returns [String current=null] : iv_ruleInteger= ruleInteger EOF ;
    public final String entryRuleInteger() throws RecognitionException {
        String current = null;

        AntlrDatatypeRuleToken iv_ruleInteger = null;


        try {
            // InternalRsamlText.g:4704:47: (iv_ruleInteger= ruleInteger EOF )
            // InternalRsamlText.g:4705:2: iv_ruleInteger= ruleInteger EOF
            {
             newCompositeNode(grammarAccess.getIntegerRule()); 
            pushFollow(FOLLOW_1);
            iv_ruleInteger=ruleInteger();

            state._fsp--;

             current =iv_ruleInteger.getText(); 
            match(input,EOF,FOLLOW_2); 

            }

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "entryRuleInteger"


    // $ANTLR start "ruleInteger"
    // InternalRsamlText.g:4711:1: ruleInteger returns [AntlrDatatypeRuleToken current=new AntlrDatatypeRuleToken()] : this_NUMBER_0= RULE_NUMBER ;
    public final AntlrDatatypeRuleToken ruleInteger() throws RecognitionException {
        AntlrDatatypeRuleToken current = new AntlrDatatypeRuleToken();

        Token this_NUMBER_0=null;


        	enterRule();

        try {
            // InternalRsamlText.g:4717:2: (this_NUMBER_0= RULE_NUMBER )
            // InternalRsamlText.g:4718:2: this_NUMBER_0= RULE_NUMBER
            {
            this_NUMBER_0=(Token)match(input,RULE_NUMBER,FOLLOW_2); 

            		current.merge(this_NUMBER_0);
            	

            		newLeafNode(this_NUMBER_0, grammarAccess.getIntegerAccess().getNUMBERTerminalRuleCall());
            	

            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "ruleInteger"


    // $ANTLR start "ruleArchitectureCategory"
    // InternalRsamlText.g:4728:1: ruleArchitectureCategory returns [Enumerator current=null] : ( (enumLiteral_0= 'centralized' ) | (enumLiteral_1= 'hierarchical' ) | (enumLiteral_2= 'behavioral' ) | (enumLiteral_3= 'hybrid' ) | (enumLiteral_4= 'other' ) ) ;
    public final Enumerator ruleArchitectureCategory() throws RecognitionException {
        Enumerator current = null;

        Token enumLiteral_0=null;
        Token enumLiteral_1=null;
        Token enumLiteral_2=null;
        Token enumLiteral_3=null;
        Token enumLiteral_4=null;


        	enterRule();

        try {
            // InternalRsamlText.g:4734:2: ( ( (enumLiteral_0= 'centralized' ) | (enumLiteral_1= 'hierarchical' ) | (enumLiteral_2= 'behavioral' ) | (enumLiteral_3= 'hybrid' ) | (enumLiteral_4= 'other' ) ) )
            // InternalRsamlText.g:4735:2: ( (enumLiteral_0= 'centralized' ) | (enumLiteral_1= 'hierarchical' ) | (enumLiteral_2= 'behavioral' ) | (enumLiteral_3= 'hybrid' ) | (enumLiteral_4= 'other' ) )
            {
            // InternalRsamlText.g:4735:2: ( (enumLiteral_0= 'centralized' ) | (enumLiteral_1= 'hierarchical' ) | (enumLiteral_2= 'behavioral' ) | (enumLiteral_3= 'hybrid' ) | (enumLiteral_4= 'other' ) )
            int alt59=5;
            switch ( input.LA(1) ) {
            case 82:
                {
                alt59=1;
                }
                break;
            case 83:
                {
                alt59=2;
                }
                break;
            case 84:
                {
                alt59=3;
                }
                break;
            case 85:
                {
                alt59=4;
                }
                break;
            case 86:
                {
                alt59=5;
                }
                break;
            default:
                NoViableAltException nvae =
                    new NoViableAltException("", 59, 0, input);

                throw nvae;
            }

            switch (alt59) {
                case 1 :
                    // InternalRsamlText.g:4736:3: (enumLiteral_0= 'centralized' )
                    {
                    // InternalRsamlText.g:4736:3: (enumLiteral_0= 'centralized' )
                    // InternalRsamlText.g:4737:4: enumLiteral_0= 'centralized'
                    {
                    enumLiteral_0=(Token)match(input,82,FOLLOW_2); 

                    				current = grammarAccess.getArchitectureCategoryAccess().getCentralizedEnumLiteralDeclaration_0().getEnumLiteral().getInstance();
                    				newLeafNode(enumLiteral_0, grammarAccess.getArchitectureCategoryAccess().getCentralizedEnumLiteralDeclaration_0());
                    			

                    }


                    }
                    break;
                case 2 :
                    // InternalRsamlText.g:4744:3: (enumLiteral_1= 'hierarchical' )
                    {
                    // InternalRsamlText.g:4744:3: (enumLiteral_1= 'hierarchical' )
                    // InternalRsamlText.g:4745:4: enumLiteral_1= 'hierarchical'
                    {
                    enumLiteral_1=(Token)match(input,83,FOLLOW_2); 

                    				current = grammarAccess.getArchitectureCategoryAccess().getHierarchicalEnumLiteralDeclaration_1().getEnumLiteral().getInstance();
                    				newLeafNode(enumLiteral_1, grammarAccess.getArchitectureCategoryAccess().getHierarchicalEnumLiteralDeclaration_1());
                    			

                    }


                    }
                    break;
                case 3 :
                    // InternalRsamlText.g:4752:3: (enumLiteral_2= 'behavioral' )
                    {
                    // InternalRsamlText.g:4752:3: (enumLiteral_2= 'behavioral' )
                    // InternalRsamlText.g:4753:4: enumLiteral_2= 'behavioral'
                    {
                    enumLiteral_2=(Token)match(input,84,FOLLOW_2); 

                    				current = grammarAccess.getArchitectureCategoryAccess().getBehavioralEnumLiteralDeclaration_2().getEnumLiteral().getInstance();
                    				newLeafNode(enumLiteral_2, grammarAccess.getArchitectureCategoryAccess().getBehavioralEnumLiteralDeclaration_2());
                    			

                    }


                    }
                    break;
                case 4 :
                    // InternalRsamlText.g:4760:3: (enumLiteral_3= 'hybrid' )
                    {
                    // InternalRsamlText.g:4760:3: (enumLiteral_3= 'hybrid' )
                    // InternalRsamlText.g:4761:4: enumLiteral_3= 'hybrid'
                    {
                    enumLiteral_3=(Token)match(input,85,FOLLOW_2); 

                    				current = grammarAccess.getArchitectureCategoryAccess().getHybridEnumLiteralDeclaration_3().getEnumLiteral().getInstance();
                    				newLeafNode(enumLiteral_3, grammarAccess.getArchitectureCategoryAccess().getHybridEnumLiteralDeclaration_3());
                    			

                    }


                    }
                    break;
                case 5 :
                    // InternalRsamlText.g:4768:3: (enumLiteral_4= 'other' )
                    {
                    // InternalRsamlText.g:4768:3: (enumLiteral_4= 'other' )
                    // InternalRsamlText.g:4769:4: enumLiteral_4= 'other'
                    {
                    enumLiteral_4=(Token)match(input,86,FOLLOW_2); 

                    				current = grammarAccess.getArchitectureCategoryAccess().getOtherEnumLiteralDeclaration_4().getEnumLiteral().getInstance();
                    				newLeafNode(enumLiteral_4, grammarAccess.getArchitectureCategoryAccess().getOtherEnumLiteralDeclaration_4());
                    			

                    }


                    }
                    break;

            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "ruleArchitectureCategory"


    // $ANTLR start "ruleElementType"
    // InternalRsamlText.g:4779:1: ruleElementType returns [Enumerator current=null] : ( (enumLiteral_0= 'simple' ) | (enumLiteral_1= 'realTime' ) ) ;
    public final Enumerator ruleElementType() throws RecognitionException {
        Enumerator current = null;

        Token enumLiteral_0=null;
        Token enumLiteral_1=null;


        	enterRule();

        try {
            // InternalRsamlText.g:4785:2: ( ( (enumLiteral_0= 'simple' ) | (enumLiteral_1= 'realTime' ) ) )
            // InternalRsamlText.g:4786:2: ( (enumLiteral_0= 'simple' ) | (enumLiteral_1= 'realTime' ) )
            {
            // InternalRsamlText.g:4786:2: ( (enumLiteral_0= 'simple' ) | (enumLiteral_1= 'realTime' ) )
            int alt60=2;
            int LA60_0 = input.LA(1);

            if ( (LA60_0==87) ) {
                alt60=1;
            }
            else if ( (LA60_0==88) ) {
                alt60=2;
            }
            else {
                NoViableAltException nvae =
                    new NoViableAltException("", 60, 0, input);

                throw nvae;
            }
            switch (alt60) {
                case 1 :
                    // InternalRsamlText.g:4787:3: (enumLiteral_0= 'simple' )
                    {
                    // InternalRsamlText.g:4787:3: (enumLiteral_0= 'simple' )
                    // InternalRsamlText.g:4788:4: enumLiteral_0= 'simple'
                    {
                    enumLiteral_0=(Token)match(input,87,FOLLOW_2); 

                    				current = grammarAccess.getElementTypeAccess().getSimpleEnumLiteralDeclaration_0().getEnumLiteral().getInstance();
                    				newLeafNode(enumLiteral_0, grammarAccess.getElementTypeAccess().getSimpleEnumLiteralDeclaration_0());
                    			

                    }


                    }
                    break;
                case 2 :
                    // InternalRsamlText.g:4795:3: (enumLiteral_1= 'realTime' )
                    {
                    // InternalRsamlText.g:4795:3: (enumLiteral_1= 'realTime' )
                    // InternalRsamlText.g:4796:4: enumLiteral_1= 'realTime'
                    {
                    enumLiteral_1=(Token)match(input,88,FOLLOW_2); 

                    				current = grammarAccess.getElementTypeAccess().getRealTimeEnumLiteralDeclaration_1().getEnumLiteral().getInstance();
                    				newLeafNode(enumLiteral_1, grammarAccess.getElementTypeAccess().getRealTimeEnumLiteralDeclaration_1());
                    			

                    }


                    }
                    break;

            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "ruleElementType"


    // $ANTLR start "ruleExecutionType"
    // InternalRsamlText.g:4806:1: ruleExecutionType returns [Enumerator current=null] : ( (enumLiteral_0= 'periodic' ) | (enumLiteral_1= 'sporadic' ) | (enumLiteral_2= 'aperiodic' ) ) ;
    public final Enumerator ruleExecutionType() throws RecognitionException {
        Enumerator current = null;

        Token enumLiteral_0=null;
        Token enumLiteral_1=null;
        Token enumLiteral_2=null;


        	enterRule();

        try {
            // InternalRsamlText.g:4812:2: ( ( (enumLiteral_0= 'periodic' ) | (enumLiteral_1= 'sporadic' ) | (enumLiteral_2= 'aperiodic' ) ) )
            // InternalRsamlText.g:4813:2: ( (enumLiteral_0= 'periodic' ) | (enumLiteral_1= 'sporadic' ) | (enumLiteral_2= 'aperiodic' ) )
            {
            // InternalRsamlText.g:4813:2: ( (enumLiteral_0= 'periodic' ) | (enumLiteral_1= 'sporadic' ) | (enumLiteral_2= 'aperiodic' ) )
            int alt61=3;
            switch ( input.LA(1) ) {
            case 89:
                {
                alt61=1;
                }
                break;
            case 90:
                {
                alt61=2;
                }
                break;
            case 91:
                {
                alt61=3;
                }
                break;
            default:
                NoViableAltException nvae =
                    new NoViableAltException("", 61, 0, input);

                throw nvae;
            }

            switch (alt61) {
                case 1 :
                    // InternalRsamlText.g:4814:3: (enumLiteral_0= 'periodic' )
                    {
                    // InternalRsamlText.g:4814:3: (enumLiteral_0= 'periodic' )
                    // InternalRsamlText.g:4815:4: enumLiteral_0= 'periodic'
                    {
                    enumLiteral_0=(Token)match(input,89,FOLLOW_2); 

                    				current = grammarAccess.getExecutionTypeAccess().getPeriodicEnumLiteralDeclaration_0().getEnumLiteral().getInstance();
                    				newLeafNode(enumLiteral_0, grammarAccess.getExecutionTypeAccess().getPeriodicEnumLiteralDeclaration_0());
                    			

                    }


                    }
                    break;
                case 2 :
                    // InternalRsamlText.g:4822:3: (enumLiteral_1= 'sporadic' )
                    {
                    // InternalRsamlText.g:4822:3: (enumLiteral_1= 'sporadic' )
                    // InternalRsamlText.g:4823:4: enumLiteral_1= 'sporadic'
                    {
                    enumLiteral_1=(Token)match(input,90,FOLLOW_2); 

                    				current = grammarAccess.getExecutionTypeAccess().getSporadicEnumLiteralDeclaration_1().getEnumLiteral().getInstance();
                    				newLeafNode(enumLiteral_1, grammarAccess.getExecutionTypeAccess().getSporadicEnumLiteralDeclaration_1());
                    			

                    }


                    }
                    break;
                case 3 :
                    // InternalRsamlText.g:4830:3: (enumLiteral_2= 'aperiodic' )
                    {
                    // InternalRsamlText.g:4830:3: (enumLiteral_2= 'aperiodic' )
                    // InternalRsamlText.g:4831:4: enumLiteral_2= 'aperiodic'
                    {
                    enumLiteral_2=(Token)match(input,91,FOLLOW_2); 

                    				current = grammarAccess.getExecutionTypeAccess().getAperiodicEnumLiteralDeclaration_2().getEnumLiteral().getInstance();
                    				newLeafNode(enumLiteral_2, grammarAccess.getExecutionTypeAccess().getAperiodicEnumLiteralDeclaration_2());
                    			

                    }


                    }
                    break;

            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "ruleExecutionType"


    // $ANTLR start "ruleTimeUnit"
    // InternalRsamlText.g:4841:1: ruleTimeUnit returns [Enumerator current=null] : ( (enumLiteral_0= 'ns' ) | (enumLiteral_1= 'us' ) | (enumLiteral_2= 'ms' ) | (enumLiteral_3= 's' ) ) ;
    public final Enumerator ruleTimeUnit() throws RecognitionException {
        Enumerator current = null;

        Token enumLiteral_0=null;
        Token enumLiteral_1=null;
        Token enumLiteral_2=null;
        Token enumLiteral_3=null;


        	enterRule();

        try {
            // InternalRsamlText.g:4847:2: ( ( (enumLiteral_0= 'ns' ) | (enumLiteral_1= 'us' ) | (enumLiteral_2= 'ms' ) | (enumLiteral_3= 's' ) ) )
            // InternalRsamlText.g:4848:2: ( (enumLiteral_0= 'ns' ) | (enumLiteral_1= 'us' ) | (enumLiteral_2= 'ms' ) | (enumLiteral_3= 's' ) )
            {
            // InternalRsamlText.g:4848:2: ( (enumLiteral_0= 'ns' ) | (enumLiteral_1= 'us' ) | (enumLiteral_2= 'ms' ) | (enumLiteral_3= 's' ) )
            int alt62=4;
            switch ( input.LA(1) ) {
            case 92:
                {
                alt62=1;
                }
                break;
            case 93:
                {
                alt62=2;
                }
                break;
            case 94:
                {
                alt62=3;
                }
                break;
            case 95:
                {
                alt62=4;
                }
                break;
            default:
                NoViableAltException nvae =
                    new NoViableAltException("", 62, 0, input);

                throw nvae;
            }

            switch (alt62) {
                case 1 :
                    // InternalRsamlText.g:4849:3: (enumLiteral_0= 'ns' )
                    {
                    // InternalRsamlText.g:4849:3: (enumLiteral_0= 'ns' )
                    // InternalRsamlText.g:4850:4: enumLiteral_0= 'ns'
                    {
                    enumLiteral_0=(Token)match(input,92,FOLLOW_2); 

                    				current = grammarAccess.getTimeUnitAccess().getNsEnumLiteralDeclaration_0().getEnumLiteral().getInstance();
                    				newLeafNode(enumLiteral_0, grammarAccess.getTimeUnitAccess().getNsEnumLiteralDeclaration_0());
                    			

                    }


                    }
                    break;
                case 2 :
                    // InternalRsamlText.g:4857:3: (enumLiteral_1= 'us' )
                    {
                    // InternalRsamlText.g:4857:3: (enumLiteral_1= 'us' )
                    // InternalRsamlText.g:4858:4: enumLiteral_1= 'us'
                    {
                    enumLiteral_1=(Token)match(input,93,FOLLOW_2); 

                    				current = grammarAccess.getTimeUnitAccess().getUsEnumLiteralDeclaration_1().getEnumLiteral().getInstance();
                    				newLeafNode(enumLiteral_1, grammarAccess.getTimeUnitAccess().getUsEnumLiteralDeclaration_1());
                    			

                    }


                    }
                    break;
                case 3 :
                    // InternalRsamlText.g:4865:3: (enumLiteral_2= 'ms' )
                    {
                    // InternalRsamlText.g:4865:3: (enumLiteral_2= 'ms' )
                    // InternalRsamlText.g:4866:4: enumLiteral_2= 'ms'
                    {
                    enumLiteral_2=(Token)match(input,94,FOLLOW_2); 

                    				current = grammarAccess.getTimeUnitAccess().getMsEnumLiteralDeclaration_2().getEnumLiteral().getInstance();
                    				newLeafNode(enumLiteral_2, grammarAccess.getTimeUnitAccess().getMsEnumLiteralDeclaration_2());
                    			

                    }


                    }
                    break;
                case 4 :
                    // InternalRsamlText.g:4873:3: (enumLiteral_3= 's' )
                    {
                    // InternalRsamlText.g:4873:3: (enumLiteral_3= 's' )
                    // InternalRsamlText.g:4874:4: enumLiteral_3= 's'
                    {
                    enumLiteral_3=(Token)match(input,95,FOLLOW_2); 

                    				current = grammarAccess.getTimeUnitAccess().getSEnumLiteralDeclaration_3().getEnumLiteral().getInstance();
                    				newLeafNode(enumLiteral_3, grammarAccess.getTimeUnitAccess().getSEnumLiteralDeclaration_3());
                    			

                    }


                    }
                    break;

            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "ruleTimeUnit"


    // $ANTLR start "ruleSynchronisationType"
    // InternalRsamlText.g:4884:1: ruleSynchronisationType returns [Enumerator current=null] : ( (enumLiteral_0= 'synchronous' ) | (enumLiteral_1= 'asynchronous' ) ) ;
    public final Enumerator ruleSynchronisationType() throws RecognitionException {
        Enumerator current = null;

        Token enumLiteral_0=null;
        Token enumLiteral_1=null;


        	enterRule();

        try {
            // InternalRsamlText.g:4890:2: ( ( (enumLiteral_0= 'synchronous' ) | (enumLiteral_1= 'asynchronous' ) ) )
            // InternalRsamlText.g:4891:2: ( (enumLiteral_0= 'synchronous' ) | (enumLiteral_1= 'asynchronous' ) )
            {
            // InternalRsamlText.g:4891:2: ( (enumLiteral_0= 'synchronous' ) | (enumLiteral_1= 'asynchronous' ) )
            int alt63=2;
            int LA63_0 = input.LA(1);

            if ( (LA63_0==96) ) {
                alt63=1;
            }
            else if ( (LA63_0==97) ) {
                alt63=2;
            }
            else {
                NoViableAltException nvae =
                    new NoViableAltException("", 63, 0, input);

                throw nvae;
            }
            switch (alt63) {
                case 1 :
                    // InternalRsamlText.g:4892:3: (enumLiteral_0= 'synchronous' )
                    {
                    // InternalRsamlText.g:4892:3: (enumLiteral_0= 'synchronous' )
                    // InternalRsamlText.g:4893:4: enumLiteral_0= 'synchronous'
                    {
                    enumLiteral_0=(Token)match(input,96,FOLLOW_2); 

                    				current = grammarAccess.getSynchronisationTypeAccess().getSynchronousEnumLiteralDeclaration_0().getEnumLiteral().getInstance();
                    				newLeafNode(enumLiteral_0, grammarAccess.getSynchronisationTypeAccess().getSynchronousEnumLiteralDeclaration_0());
                    			

                    }


                    }
                    break;
                case 2 :
                    // InternalRsamlText.g:4900:3: (enumLiteral_1= 'asynchronous' )
                    {
                    // InternalRsamlText.g:4900:3: (enumLiteral_1= 'asynchronous' )
                    // InternalRsamlText.g:4901:4: enumLiteral_1= 'asynchronous'
                    {
                    enumLiteral_1=(Token)match(input,97,FOLLOW_2); 

                    				current = grammarAccess.getSynchronisationTypeAccess().getAsynchronousEnumLiteralDeclaration_1().getEnumLiteral().getInstance();
                    				newLeafNode(enumLiteral_1, grammarAccess.getSynchronisationTypeAccess().getAsynchronousEnumLiteralDeclaration_1());
                    			

                    }


                    }
                    break;

            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "ruleSynchronisationType"


    // $ANTLR start "ruleSchedulingPolicy"
    // InternalRsamlText.g:4911:1: ruleSchedulingPolicy returns [Enumerator current=null] : ( (enumLiteral_0= 'FIFO' ) | (enumLiteral_1= 'SJF' ) | (enumLiteral_2= 'RR' ) | (enumLiteral_3= 'RM' ) | (enumLiteral_4= 'DM' ) | (enumLiteral_5= 'EDF' ) | (enumLiteral_6= 'LLF' ) | (enumLiteral_7= 'OTHER' ) ) ;
    public final Enumerator ruleSchedulingPolicy() throws RecognitionException {
        Enumerator current = null;

        Token enumLiteral_0=null;
        Token enumLiteral_1=null;
        Token enumLiteral_2=null;
        Token enumLiteral_3=null;
        Token enumLiteral_4=null;
        Token enumLiteral_5=null;
        Token enumLiteral_6=null;
        Token enumLiteral_7=null;


        	enterRule();

        try {
            // InternalRsamlText.g:4917:2: ( ( (enumLiteral_0= 'FIFO' ) | (enumLiteral_1= 'SJF' ) | (enumLiteral_2= 'RR' ) | (enumLiteral_3= 'RM' ) | (enumLiteral_4= 'DM' ) | (enumLiteral_5= 'EDF' ) | (enumLiteral_6= 'LLF' ) | (enumLiteral_7= 'OTHER' ) ) )
            // InternalRsamlText.g:4918:2: ( (enumLiteral_0= 'FIFO' ) | (enumLiteral_1= 'SJF' ) | (enumLiteral_2= 'RR' ) | (enumLiteral_3= 'RM' ) | (enumLiteral_4= 'DM' ) | (enumLiteral_5= 'EDF' ) | (enumLiteral_6= 'LLF' ) | (enumLiteral_7= 'OTHER' ) )
            {
            // InternalRsamlText.g:4918:2: ( (enumLiteral_0= 'FIFO' ) | (enumLiteral_1= 'SJF' ) | (enumLiteral_2= 'RR' ) | (enumLiteral_3= 'RM' ) | (enumLiteral_4= 'DM' ) | (enumLiteral_5= 'EDF' ) | (enumLiteral_6= 'LLF' ) | (enumLiteral_7= 'OTHER' ) )
            int alt64=8;
            switch ( input.LA(1) ) {
            case 98:
                {
                alt64=1;
                }
                break;
            case 99:
                {
                alt64=2;
                }
                break;
            case 100:
                {
                alt64=3;
                }
                break;
            case 101:
                {
                alt64=4;
                }
                break;
            case 102:
                {
                alt64=5;
                }
                break;
            case 103:
                {
                alt64=6;
                }
                break;
            case 104:
                {
                alt64=7;
                }
                break;
            case 105:
                {
                alt64=8;
                }
                break;
            default:
                NoViableAltException nvae =
                    new NoViableAltException("", 64, 0, input);

                throw nvae;
            }

            switch (alt64) {
                case 1 :
                    // InternalRsamlText.g:4919:3: (enumLiteral_0= 'FIFO' )
                    {
                    // InternalRsamlText.g:4919:3: (enumLiteral_0= 'FIFO' )
                    // InternalRsamlText.g:4920:4: enumLiteral_0= 'FIFO'
                    {
                    enumLiteral_0=(Token)match(input,98,FOLLOW_2); 

                    				current = grammarAccess.getSchedulingPolicyAccess().getFIFOEnumLiteralDeclaration_0().getEnumLiteral().getInstance();
                    				newLeafNode(enumLiteral_0, grammarAccess.getSchedulingPolicyAccess().getFIFOEnumLiteralDeclaration_0());
                    			

                    }


                    }
                    break;
                case 2 :
                    // InternalRsamlText.g:4927:3: (enumLiteral_1= 'SJF' )
                    {
                    // InternalRsamlText.g:4927:3: (enumLiteral_1= 'SJF' )
                    // InternalRsamlText.g:4928:4: enumLiteral_1= 'SJF'
                    {
                    enumLiteral_1=(Token)match(input,99,FOLLOW_2); 

                    				current = grammarAccess.getSchedulingPolicyAccess().getSJFEnumLiteralDeclaration_1().getEnumLiteral().getInstance();
                    				newLeafNode(enumLiteral_1, grammarAccess.getSchedulingPolicyAccess().getSJFEnumLiteralDeclaration_1());
                    			

                    }


                    }
                    break;
                case 3 :
                    // InternalRsamlText.g:4935:3: (enumLiteral_2= 'RR' )
                    {
                    // InternalRsamlText.g:4935:3: (enumLiteral_2= 'RR' )
                    // InternalRsamlText.g:4936:4: enumLiteral_2= 'RR'
                    {
                    enumLiteral_2=(Token)match(input,100,FOLLOW_2); 

                    				current = grammarAccess.getSchedulingPolicyAccess().getRREnumLiteralDeclaration_2().getEnumLiteral().getInstance();
                    				newLeafNode(enumLiteral_2, grammarAccess.getSchedulingPolicyAccess().getRREnumLiteralDeclaration_2());
                    			

                    }


                    }
                    break;
                case 4 :
                    // InternalRsamlText.g:4943:3: (enumLiteral_3= 'RM' )
                    {
                    // InternalRsamlText.g:4943:3: (enumLiteral_3= 'RM' )
                    // InternalRsamlText.g:4944:4: enumLiteral_3= 'RM'
                    {
                    enumLiteral_3=(Token)match(input,101,FOLLOW_2); 

                    				current = grammarAccess.getSchedulingPolicyAccess().getRMEnumLiteralDeclaration_3().getEnumLiteral().getInstance();
                    				newLeafNode(enumLiteral_3, grammarAccess.getSchedulingPolicyAccess().getRMEnumLiteralDeclaration_3());
                    			

                    }


                    }
                    break;
                case 5 :
                    // InternalRsamlText.g:4951:3: (enumLiteral_4= 'DM' )
                    {
                    // InternalRsamlText.g:4951:3: (enumLiteral_4= 'DM' )
                    // InternalRsamlText.g:4952:4: enumLiteral_4= 'DM'
                    {
                    enumLiteral_4=(Token)match(input,102,FOLLOW_2); 

                    				current = grammarAccess.getSchedulingPolicyAccess().getDMEnumLiteralDeclaration_4().getEnumLiteral().getInstance();
                    				newLeafNode(enumLiteral_4, grammarAccess.getSchedulingPolicyAccess().getDMEnumLiteralDeclaration_4());
                    			

                    }


                    }
                    break;
                case 6 :
                    // InternalRsamlText.g:4959:3: (enumLiteral_5= 'EDF' )
                    {
                    // InternalRsamlText.g:4959:3: (enumLiteral_5= 'EDF' )
                    // InternalRsamlText.g:4960:4: enumLiteral_5= 'EDF'
                    {
                    enumLiteral_5=(Token)match(input,103,FOLLOW_2); 

                    				current = grammarAccess.getSchedulingPolicyAccess().getEDFEnumLiteralDeclaration_5().getEnumLiteral().getInstance();
                    				newLeafNode(enumLiteral_5, grammarAccess.getSchedulingPolicyAccess().getEDFEnumLiteralDeclaration_5());
                    			

                    }


                    }
                    break;
                case 7 :
                    // InternalRsamlText.g:4967:3: (enumLiteral_6= 'LLF' )
                    {
                    // InternalRsamlText.g:4967:3: (enumLiteral_6= 'LLF' )
                    // InternalRsamlText.g:4968:4: enumLiteral_6= 'LLF'
                    {
                    enumLiteral_6=(Token)match(input,104,FOLLOW_2); 

                    				current = grammarAccess.getSchedulingPolicyAccess().getLLFEnumLiteralDeclaration_6().getEnumLiteral().getInstance();
                    				newLeafNode(enumLiteral_6, grammarAccess.getSchedulingPolicyAccess().getLLFEnumLiteralDeclaration_6());
                    			

                    }


                    }
                    break;
                case 8 :
                    // InternalRsamlText.g:4975:3: (enumLiteral_7= 'OTHER' )
                    {
                    // InternalRsamlText.g:4975:3: (enumLiteral_7= 'OTHER' )
                    // InternalRsamlText.g:4976:4: enumLiteral_7= 'OTHER'
                    {
                    enumLiteral_7=(Token)match(input,105,FOLLOW_2); 

                    				current = grammarAccess.getSchedulingPolicyAccess().getOTHEREnumLiteralDeclaration_7().getEnumLiteral().getInstance();
                    				newLeafNode(enumLiteral_7, grammarAccess.getSchedulingPolicyAccess().getOTHEREnumLiteralDeclaration_7());
                    			

                    }


                    }
                    break;

            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "ruleSchedulingPolicy"


    // $ANTLR start "ruleDataType"
    // InternalRsamlText.g:4986:1: ruleDataType returns [Enumerator current=null] : ( (enumLiteral_0= 'numeric' ) | (enumLiteral_1= 'alphanumeric' ) | (enumLiteral_2= 'boolean' ) | (enumLiteral_3= 'structured' ) ) ;
    public final Enumerator ruleDataType() throws RecognitionException {
        Enumerator current = null;

        Token enumLiteral_0=null;
        Token enumLiteral_1=null;
        Token enumLiteral_2=null;
        Token enumLiteral_3=null;


        	enterRule();

        try {
            // InternalRsamlText.g:4992:2: ( ( (enumLiteral_0= 'numeric' ) | (enumLiteral_1= 'alphanumeric' ) | (enumLiteral_2= 'boolean' ) | (enumLiteral_3= 'structured' ) ) )
            // InternalRsamlText.g:4993:2: ( (enumLiteral_0= 'numeric' ) | (enumLiteral_1= 'alphanumeric' ) | (enumLiteral_2= 'boolean' ) | (enumLiteral_3= 'structured' ) )
            {
            // InternalRsamlText.g:4993:2: ( (enumLiteral_0= 'numeric' ) | (enumLiteral_1= 'alphanumeric' ) | (enumLiteral_2= 'boolean' ) | (enumLiteral_3= 'structured' ) )
            int alt65=4;
            switch ( input.LA(1) ) {
            case 106:
                {
                alt65=1;
                }
                break;
            case 107:
                {
                alt65=2;
                }
                break;
            case 108:
                {
                alt65=3;
                }
                break;
            case 109:
                {
                alt65=4;
                }
                break;
            default:
                NoViableAltException nvae =
                    new NoViableAltException("", 65, 0, input);

                throw nvae;
            }

            switch (alt65) {
                case 1 :
                    // InternalRsamlText.g:4994:3: (enumLiteral_0= 'numeric' )
                    {
                    // InternalRsamlText.g:4994:3: (enumLiteral_0= 'numeric' )
                    // InternalRsamlText.g:4995:4: enumLiteral_0= 'numeric'
                    {
                    enumLiteral_0=(Token)match(input,106,FOLLOW_2); 

                    				current = grammarAccess.getDataTypeAccess().getNumericEnumLiteralDeclaration_0().getEnumLiteral().getInstance();
                    				newLeafNode(enumLiteral_0, grammarAccess.getDataTypeAccess().getNumericEnumLiteralDeclaration_0());
                    			

                    }


                    }
                    break;
                case 2 :
                    // InternalRsamlText.g:5002:3: (enumLiteral_1= 'alphanumeric' )
                    {
                    // InternalRsamlText.g:5002:3: (enumLiteral_1= 'alphanumeric' )
                    // InternalRsamlText.g:5003:4: enumLiteral_1= 'alphanumeric'
                    {
                    enumLiteral_1=(Token)match(input,107,FOLLOW_2); 

                    				current = grammarAccess.getDataTypeAccess().getAlphanumericEnumLiteralDeclaration_1().getEnumLiteral().getInstance();
                    				newLeafNode(enumLiteral_1, grammarAccess.getDataTypeAccess().getAlphanumericEnumLiteralDeclaration_1());
                    			

                    }


                    }
                    break;
                case 3 :
                    // InternalRsamlText.g:5010:3: (enumLiteral_2= 'boolean' )
                    {
                    // InternalRsamlText.g:5010:3: (enumLiteral_2= 'boolean' )
                    // InternalRsamlText.g:5011:4: enumLiteral_2= 'boolean'
                    {
                    enumLiteral_2=(Token)match(input,108,FOLLOW_2); 

                    				current = grammarAccess.getDataTypeAccess().getBooleanEnumLiteralDeclaration_2().getEnumLiteral().getInstance();
                    				newLeafNode(enumLiteral_2, grammarAccess.getDataTypeAccess().getBooleanEnumLiteralDeclaration_2());
                    			

                    }


                    }
                    break;
                case 4 :
                    // InternalRsamlText.g:5018:3: (enumLiteral_3= 'structured' )
                    {
                    // InternalRsamlText.g:5018:3: (enumLiteral_3= 'structured' )
                    // InternalRsamlText.g:5019:4: enumLiteral_3= 'structured'
                    {
                    enumLiteral_3=(Token)match(input,109,FOLLOW_2); 

                    				current = grammarAccess.getDataTypeAccess().getStructuredEnumLiteralDeclaration_3().getEnumLiteral().getInstance();
                    				newLeafNode(enumLiteral_3, grammarAccess.getDataTypeAccess().getStructuredEnumLiteralDeclaration_3());
                    			

                    }


                    }
                    break;

            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "ruleDataType"


    // $ANTLR start "ruleNodeLifecycle"
    // InternalRsamlText.g:5029:1: ruleNodeLifecycle returns [Enumerator current=null] : ( (enumLiteral_0= 'plain' ) | (enumLiteral_1= 'managed' ) ) ;
    public final Enumerator ruleNodeLifecycle() throws RecognitionException {
        Enumerator current = null;

        Token enumLiteral_0=null;
        Token enumLiteral_1=null;


        	enterRule();

        try {
            // InternalRsamlText.g:5035:2: ( ( (enumLiteral_0= 'plain' ) | (enumLiteral_1= 'managed' ) ) )
            // InternalRsamlText.g:5036:2: ( (enumLiteral_0= 'plain' ) | (enumLiteral_1= 'managed' ) )
            {
            // InternalRsamlText.g:5036:2: ( (enumLiteral_0= 'plain' ) | (enumLiteral_1= 'managed' ) )
            int alt66=2;
            int LA66_0 = input.LA(1);

            if ( (LA66_0==112) ) {
                alt66=1;
            }
            else if ( (LA66_0==113) ) {
                alt66=2;
            }
            else {
                NoViableAltException nvae =
                    new NoViableAltException("", 66, 0, input);

                throw nvae;
            }
            switch (alt66) {
                case 1 :
                    // InternalRsamlText.g:5037:3: (enumLiteral_0= 'plain' )
                    {
                    // InternalRsamlText.g:5037:3: (enumLiteral_0= 'plain' )
                    // InternalRsamlText.g:5038:4: enumLiteral_0= 'plain'
                    {
                    enumLiteral_0=(Token)match(input,112,FOLLOW_2); 

                    				current = grammarAccess.getNodeLifecycleAccess().getPlainEnumLiteralDeclaration_0().getEnumLiteral().getInstance();
                    				newLeafNode(enumLiteral_0, grammarAccess.getNodeLifecycleAccess().getPlainEnumLiteralDeclaration_0());
                    			

                    }


                    }
                    break;
                case 2 :
                    // InternalRsamlText.g:5045:3: (enumLiteral_1= 'managed' )
                    {
                    // InternalRsamlText.g:5045:3: (enumLiteral_1= 'managed' )
                    // InternalRsamlText.g:5046:4: enumLiteral_1= 'managed'
                    {
                    enumLiteral_1=(Token)match(input,113,FOLLOW_2); 

                    				current = grammarAccess.getNodeLifecycleAccess().getManagedEnumLiteralDeclaration_1().getEnumLiteral().getInstance();
                    				newLeafNode(enumLiteral_1, grammarAccess.getNodeLifecycleAccess().getManagedEnumLiteralDeclaration_1());
                    			

                    }


                    }
                    break;

            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "ruleNodeLifecycle"


    // $ANTLR start "rulePackageLayout"
    // InternalRsamlText.g:5056:1: rulePackageLayout returns [Enumerator current=null] : ( (enumLiteral_0= 'single' ) | (enumLiteral_1= 'perLayer' ) | (enumLiteral_2= 'perProcessor' ) ) ;
    public final Enumerator rulePackageLayout() throws RecognitionException {
        Enumerator current = null;

        Token enumLiteral_0=null;
        Token enumLiteral_1=null;
        Token enumLiteral_2=null;


        	enterRule();

        try {
            // InternalRsamlText.g:5062:2: ( ( (enumLiteral_0= 'single' ) | (enumLiteral_1= 'perLayer' ) | (enumLiteral_2= 'perProcessor' ) ) )
            // InternalRsamlText.g:5063:2: ( (enumLiteral_0= 'single' ) | (enumLiteral_1= 'perLayer' ) | (enumLiteral_2= 'perProcessor' ) )
            {
            // InternalRsamlText.g:5063:2: ( (enumLiteral_0= 'single' ) | (enumLiteral_1= 'perLayer' ) | (enumLiteral_2= 'perProcessor' ) )
            int alt67=3;
            switch ( input.LA(1) ) {
            case 114:
                {
                alt67=1;
                }
                break;
            case 115:
                {
                alt67=2;
                }
                break;
            case 116:
                {
                alt67=3;
                }
                break;
            default:
                NoViableAltException nvae =
                    new NoViableAltException("", 67, 0, input);

                throw nvae;
            }

            switch (alt67) {
                case 1 :
                    // InternalRsamlText.g:5064:3: (enumLiteral_0= 'single' )
                    {
                    // InternalRsamlText.g:5064:3: (enumLiteral_0= 'single' )
                    // InternalRsamlText.g:5065:4: enumLiteral_0= 'single'
                    {
                    enumLiteral_0=(Token)match(input,114,FOLLOW_2); 

                    				current = grammarAccess.getPackageLayoutAccess().getSingleEnumLiteralDeclaration_0().getEnumLiteral().getInstance();
                    				newLeafNode(enumLiteral_0, grammarAccess.getPackageLayoutAccess().getSingleEnumLiteralDeclaration_0());
                    			

                    }


                    }
                    break;
                case 2 :
                    // InternalRsamlText.g:5072:3: (enumLiteral_1= 'perLayer' )
                    {
                    // InternalRsamlText.g:5072:3: (enumLiteral_1= 'perLayer' )
                    // InternalRsamlText.g:5073:4: enumLiteral_1= 'perLayer'
                    {
                    enumLiteral_1=(Token)match(input,115,FOLLOW_2); 

                    				current = grammarAccess.getPackageLayoutAccess().getPerLayerEnumLiteralDeclaration_1().getEnumLiteral().getInstance();
                    				newLeafNode(enumLiteral_1, grammarAccess.getPackageLayoutAccess().getPerLayerEnumLiteralDeclaration_1());
                    			

                    }


                    }
                    break;
                case 3 :
                    // InternalRsamlText.g:5080:3: (enumLiteral_2= 'perProcessor' )
                    {
                    // InternalRsamlText.g:5080:3: (enumLiteral_2= 'perProcessor' )
                    // InternalRsamlText.g:5081:4: enumLiteral_2= 'perProcessor'
                    {
                    enumLiteral_2=(Token)match(input,116,FOLLOW_2); 

                    				current = grammarAccess.getPackageLayoutAccess().getPerProcessorEnumLiteralDeclaration_2().getEnumLiteral().getInstance();
                    				newLeafNode(enumLiteral_2, grammarAccess.getPackageLayoutAccess().getPerProcessorEnumLiteralDeclaration_2());
                    			

                    }


                    }
                    break;

            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "rulePackageLayout"


    // $ANTLR start "ruleLatencyKind"
    // InternalRsamlText.g:5091:1: ruleLatencyKind returns [Enumerator current=null] : ( (enumLiteral_0= 'reactionTime' ) | (enumLiteral_1= 'dataAge' ) ) ;
    public final Enumerator ruleLatencyKind() throws RecognitionException {
        Enumerator current = null;

        Token enumLiteral_0=null;
        Token enumLiteral_1=null;


        	enterRule();

        try {
            // InternalRsamlText.g:5097:2: ( ( (enumLiteral_0= 'reactionTime' ) | (enumLiteral_1= 'dataAge' ) ) )
            // InternalRsamlText.g:5098:2: ( (enumLiteral_0= 'reactionTime' ) | (enumLiteral_1= 'dataAge' ) )
            {
            // InternalRsamlText.g:5098:2: ( (enumLiteral_0= 'reactionTime' ) | (enumLiteral_1= 'dataAge' ) )
            int alt68=2;
            int LA68_0 = input.LA(1);

            if ( (LA68_0==110) ) {
                alt68=1;
            }
            else if ( (LA68_0==111) ) {
                alt68=2;
            }
            else {
                NoViableAltException nvae =
                    new NoViableAltException("", 68, 0, input);

                throw nvae;
            }
            switch (alt68) {
                case 1 :
                    // InternalRsamlText.g:5099:3: (enumLiteral_0= 'reactionTime' )
                    {
                    // InternalRsamlText.g:5099:3: (enumLiteral_0= 'reactionTime' )
                    // InternalRsamlText.g:5100:4: enumLiteral_0= 'reactionTime'
                    {
                    enumLiteral_0=(Token)match(input,110,FOLLOW_2); 

                    				current = grammarAccess.getLatencyKindAccess().getReactionTimeEnumLiteralDeclaration_0().getEnumLiteral().getInstance();
                    				newLeafNode(enumLiteral_0, grammarAccess.getLatencyKindAccess().getReactionTimeEnumLiteralDeclaration_0());
                    			

                    }


                    }
                    break;
                case 2 :
                    // InternalRsamlText.g:5107:3: (enumLiteral_1= 'dataAge' )
                    {
                    // InternalRsamlText.g:5107:3: (enumLiteral_1= 'dataAge' )
                    // InternalRsamlText.g:5108:4: enumLiteral_1= 'dataAge'
                    {
                    enumLiteral_1=(Token)match(input,111,FOLLOW_2); 

                    				current = grammarAccess.getLatencyKindAccess().getDataAgeEnumLiteralDeclaration_1().getEnumLiteral().getInstance();
                    				newLeafNode(enumLiteral_1, grammarAccess.getLatencyKindAccess().getDataAgeEnumLiteralDeclaration_1());
                    			

                    }


                    }
                    break;

            }


            }


            	leaveRule();

        }

            catch (RecognitionException re) {
                recover(input,re);
                appendSkippedTokens();
            }
        finally {
        }
        return current;
    }
    // $ANTLR end "ruleLatencyKind"

    // Delegated rules


 

    public static final BitSet FOLLOW_1 = new BitSet(new long[]{0x0000000000000000L});
    public static final BitSet FOLLOW_2 = new BitSet(new long[]{0x0000000000000002L});
    public static final BitSet FOLLOW_3 = new BitSet(new long[]{0xFFFFDFFFBFFDF830L,0x007FFFFFFFFDFFFFL});
    public static final BitSet FOLLOW_4 = new BitSet(new long[]{0x0000000000001000L});
    public static final BitSet FOLLOW_5 = new BitSet(new long[]{0x206810000207E000L,0x0000000000001091L});
    public static final BitSet FOLLOW_6 = new BitSet(new long[]{0x0000000000000000L,0x00000000007C0000L});
    public static final BitSet FOLLOW_7 = new BitSet(new long[]{0x0000000000000040L});
    public static final BitSet FOLLOW_8 = new BitSet(new long[]{0x0000000000000000L,0x0003000000000000L});
    public static final BitSet FOLLOW_9 = new BitSet(new long[]{0x0000000000000000L,0x001C000000000000L});
    public static final BitSet FOLLOW_10 = new BitSet(new long[]{0x0000000000000010L});
    public static final BitSet FOLLOW_11 = new BitSet(new long[]{0x0000000000000000L,0x00000000F0000000L});
    public static final BitSet FOLLOW_12 = new BitSet(new long[]{0x0000000000000000L,0x0000000001800000L});
    public static final BitSet FOLLOW_13 = new BitSet(new long[]{0x0000000000000000L,0x000000000E000000L});
    public static final BitSet FOLLOW_14 = new BitSet(new long[]{0x0000000000000040L,0x00E0000000000000L});
    public static final BitSet FOLLOW_15 = new BitSet(new long[]{0x000000001C0E0000L});
    public static final BitSet FOLLOW_16 = new BitSet(new long[]{0x00044181A1FE8000L});
    public static final BitSet FOLLOW_17 = new BitSet(new long[]{0x0000000000000030L});
    public static final BitSet FOLLOW_18 = new BitSet(new long[]{0x00044181E1FE8000L});
    public static final BitSet FOLLOW_19 = new BitSet(new long[]{0x0000003E01FE0000L});
    public static final BitSet FOLLOW_20 = new BitSet(new long[]{0x0000000000000000L,0x0000000300000000L});
    public static final BitSet FOLLOW_21 = new BitSet(new long[]{0x0000000000000000L,0x000003FC00000000L});
    public static final BitSet FOLLOW_22 = new BitSet(new long[]{0x0000004001FE0000L});
    public static final BitSet FOLLOW_23 = new BitSet(new long[]{0x00000E0000060000L});
    public static final BitSet FOLLOW_24 = new BitSet(new long[]{0x0000000000000000L,0x00003C0000000000L});
    public static final BitSet FOLLOW_25 = new BitSet(new long[]{0x0000200000000030L});
    public static final BitSet FOLLOW_26 = new BitSet(new long[]{0x0000200000000000L});
    public static final BitSet FOLLOW_27 = new BitSet(new long[]{0x0000000000000032L});
    public static final BitSet FOLLOW_28 = new BitSet(new long[]{0x00038000000E0000L});
    public static final BitSet FOLLOW_29 = new BitSet(new long[]{0x00100200004E0000L});
    public static final BitSet FOLLOW_30 = new BitSet(new long[]{0x0280000000060000L});
    public static final BitSet FOLLOW_31 = new BitSet(new long[]{0x0180000000060000L});
    public static final BitSet FOLLOW_32 = new BitSet(new long[]{0x0C00000000060000L});
    public static final BitSet FOLLOW_33 = new BitSet(new long[]{0x0C00000040060000L});
    public static final BitSet FOLLOW_34 = new BitSet(new long[]{0x1000000001FE0000L});
    public static final BitSet FOLLOW_35 = new BitSet(new long[]{0x1000000041FE0000L});
    public static final BitSet FOLLOW_36 = new BitSet(new long[]{0xC000000000060000L});
    public static final BitSet FOLLOW_37 = new BitSet(new long[]{0xC000000040060000L});
    public static final BitSet FOLLOW_38 = new BitSet(new long[]{0x0000000000060000L,0x000000000000000EL});
    public static final BitSet FOLLOW_39 = new BitSet(new long[]{0x0000000000060000L,0x0000000000000020L});
    public static final BitSet FOLLOW_40 = new BitSet(new long[]{0x0000020000060000L,0x0000000000000040L});
    public static final BitSet FOLLOW_41 = new BitSet(new long[]{0x0000020040060000L,0x0000000000000040L});
    public static final BitSet FOLLOW_42 = new BitSet(new long[]{0x00000004000E0000L,0x0000000000000F00L});
    public static final BitSet FOLLOW_43 = new BitSet(new long[]{0x00000004400E0000L,0x0000000000000F00L});
    public static final BitSet FOLLOW_44 = new BitSet(new long[]{0x00100000000E0000L,0x000000000001E000L});
    public static final BitSet FOLLOW_45 = new BitSet(new long[]{0x00100000400E0000L,0x000000000001E000L});
    public static final BitSet FOLLOW_46 = new BitSet(new long[]{0x0000000000000000L,0x0000C00000000000L});
    public static final BitSet FOLLOW_47 = new BitSet(new long[]{0x0000000000000002L,0x0000000000020000L});
    public static final BitSet FOLLOW_48 = new BitSet(new long[]{0xFFFFDFFFBFFDE830L,0x007FFFFFFFFDFFFFL});
    public static final BitSet FOLLOW_49 = new BitSet(new long[]{0x0000000000000000L,0x0040000000000000L});

}